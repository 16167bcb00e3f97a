/**
 * Drawing through an sRGB picture where the canvas cannot be viewed as -srgb (WebGPU
 * compatibility mode: no view formats). The page renders into `target(...)` (rgba8unorm-srgb: the
 * renderer's blending and MSAA resolve stay linear, as through an -srgb view of the canvas), then
 * `encode` copies it to the canvas texture with the sRGB encoding done in the shader
 * (wgsl/render/blit-srgb.wgsl). In core WebGPU the page draws through an -srgb view and needs none of this.
 */
import blitWgsl from '../../../wgsl/render/blit-srgb.wgsl?raw';
import { BLIT_GROUP } from '../contract/render.ts';

/** The blit's shader module's sources: its binding (BLIT_GROUP), then wgsl/render/blit-srgb.wgsl. */
export const BLIT_SHADER: readonly string[] = [BLIT_GROUP.wgsl(), blitWgsl];

export const SRGB_TARGET_FORMAT: GPUTextureFormat = 'rgba8unorm-srgb';

export class SrgbBlit {
  readonly #device: GPUDevice;
  readonly #pipeline: GPURenderPipeline;
  readonly #groupLayout: GPUBindGroupLayout;
  #target: GPUTexture | null = null;
  #group: GPUBindGroup | null = null;

  constructor(device: GPUDevice, canvasFormat: GPUTextureFormat) {
    this.#device = device;
    const module = device.createShaderModule({ label: 'srgb blit shader', code: BLIT_SHADER.join('\n') });
    this.#groupLayout = device.createBindGroupLayout({ label: 'srgb blit bind group layout', entries: BLIT_GROUP.layoutEntries() });
    this.#pipeline = device.createRenderPipeline({
      label: 'srgb blit pipeline',
      layout: device.createPipelineLayout({ label: 'srgb blit pipeline layout', bindGroupLayouts: [this.#groupLayout] }),
      vertex: { module, entryPoint: 'blitVertex' },
      fragment: { module, entryPoint: 'blitFragment', targets: [{ format: canvasFormat }] },
      primitive: { topology: 'triangle-list' },
    });
  }

  /** The texture to render into, the canvas's size (made again when that changes). */
  target(width: number, height: number): GPUTexture {
    if (!this.#target || this.#target.width !== width || this.#target.height !== height) {
      this.#target?.destroy();
      this.#target = this.#device.createTexture({
        label: 'srgb picture (compatibility mode)',
        size: [width, height],
        format: SRGB_TARGET_FORMAT,
        usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_SRC | GPUTextureUsage.COPY_DST,
      });
      this.#group = this.#device.createBindGroup({
        label: 'srgb blit bind group',
        layout: this.#groupLayout,
        entries: [{ binding: BLIT_GROUP.binding.source, resource: this.#target.createView({ label: 'srgb picture view' }) }],
      });
    }
    return this.#target;
  }

  /** Copy the picture (target()) to `canvas`, sRGB-encoded. */
  encode(encoder: GPUCommandEncoder, canvas: GPUTexture): void {
    if (!this.#group) return;
    const pass = encoder.beginRenderPass({
      label: 'srgb blit pass',
      colorAttachments: [
        { view: canvas.createView({ label: 'canvas view' }), loadOp: 'clear', storeOp: 'store', clearValue: [0, 0, 0, 1] },
      ],
    });
    pass.setPipeline(this.#pipeline);
    pass.setBindGroup(0, this.#group);
    pass.draw(3);
    pass.end();
  }

  destroy(): void {
    this.#target?.destroy();
    this.#target = null;
  }
}
