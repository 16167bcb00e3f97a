/**
 * The talk's "cost per pass": how long it takes to draw the stored tessellation once lit and
 * once into a shadow map, straight from the tessellator's buffers with drawIndexedIndirect. A
 * minimal pair of passes (Lambert shading into 1920×1080 rgba8 + depth; depth only into a
 * 2048² shadow map), so that the number measures the geometry, not a material.
 */
import { mat4 } from 'gl-matrix';
import type { TessellatedMesh } from '../src/gpu/contract/tessellated-mesh.ts';
import type { PreparedMesh } from '../src/gpu/tess/prepare.ts';

/** The benchmark's light: an orthographic box around the model, from above and to the side. */
export function benchLightViewProj(mesh: PreparedMesh): Float32Array {
  const centre = [0, 1, 2].map((i) => (mesh.bboxMin[i] + mesh.bboxMax[i]) / 2) as [number, number, number];
  const r = mesh.size / 2;
  const lightView = mat4.lookAt(mat4.create(), [centre[0] + 2 * r, centre[1] + 3 * r, centre[2] + 2 * r], centre, [0, 1, 0]);
  const lightProj = mat4.orthoZO(mat4.create(), -r, r, -r, r, 0.1 * r, 8 * r);
  return mat4.multiply(mat4.create(), lightProj, lightView) as Float32Array;
}

const SHADER = /* wgsl */ `
struct Camera { viewProj: mat4x4<f32>, light: vec4<f32> }
@group(0) @binding(0) var<uniform> camera: Camera;
struct Out { @builtin(position) clip: vec4<f32>, @location(0) normal: vec3<f32> }
@vertex fn vs(@location(0) p: vec3<f32>, @location(1) n: vec3<f32>) -> Out {
  return Out(camera.viewProj * vec4<f32>(p, 1.0), n);
}
@fragment fn fs(i: Out) -> @location(0) vec4<f32> {
  let l = max(dot(normalize(i.normal), camera.light.xyz), 0.0);
  return vec4<f32>(vec3<f32>(0.1 + 0.9 * l), 1.0);
}
@vertex fn vsDepth(@location(0) p: vec3<f32>) -> @builtin(position) vec4<f32> {
  return camera.viewProj * vec4<f32>(p, 1.0);
}`;

export async function timeDrawPasses(
  device: GPUDevice,
  mesh: TessellatedMesh,
  viewProj: Float32Array,
  lightViewProj: Float32Array,
  repeats: number,
  /** The lit pass's culling (default 'back'; the instanced comparison draws both with 'none',
   * as the instanced tessellator's own lit pipeline does). */
  litCullMode: GPUCullMode = 'back',
): Promise<{ litMs: number; shadowMs: number }> {
  const module = device.createShaderModule({ label: 'bench draw', code: SHADER });
  const vertexBuffers: GPUVertexBufferLayout[] = [
    { arrayStride: 12, attributes: [{ shaderLocation: 0, format: 'float32x3', offset: 0 }] },
    { arrayStride: 12, attributes: [{ shaderLocation: 1, format: 'float32x3', offset: 0 }] },
  ];
  const depthStencil: GPUDepthStencilState = { format: 'depth32float', depthWriteEnabled: true, depthCompare: 'less' };
  const lit = device.createRenderPipeline({
    label: 'bench lit',
    layout: 'auto',
    depthStencil,
    vertex: { module, entryPoint: 'vs', buffers: vertexBuffers },
    fragment: { module, entryPoint: 'fs', targets: [{ format: 'rgba8unorm' }] },
    primitive: { cullMode: litCullMode },
  });
  const shadow = device.createRenderPipeline({
    label: 'bench shadow',
    layout: 'auto',
    depthStencil,
    vertex: { module, entryPoint: 'vsDepth', buffers: [vertexBuffers[0]] },
    primitive: { cullMode: 'none' },
  });
  const uniform = (label: string, m: Float32Array) => {
    const b = device.createBuffer({ label, size: 80, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
    device.queue.writeBuffer(b, 0, new Float32Array([...m, 0.4, 0.8, 0.45, 0]));
    return b;
  };
  const camera = uniform('bench camera', viewProj);
  const lightCamera = uniform('bench light camera', lightViewProj);
  const litGroup = device.createBindGroup({ layout: lit.getBindGroupLayout(0), entries: [{ binding: 0, resource: { buffer: camera } }] });
  const shadowGroup = device.createBindGroup({
    layout: shadow.getBindGroupLayout(0),
    entries: [{ binding: 0, resource: { buffer: lightCamera } }],
  });
  const color = device.createTexture({
    label: 'bench color',
    size: [1920, 1080],
    format: 'rgba8unorm',
    usage: GPUTextureUsage.RENDER_ATTACHMENT,
  });
  const depth = device.createTexture({
    label: 'bench depth',
    size: [1920, 1080],
    format: 'depth32float',
    usage: GPUTextureUsage.RENDER_ATTACHMENT,
  });
  const shadowMap = device.createTexture({
    label: 'bench shadow map',
    size: [2048, 2048],
    format: 'depth32float',
    usage: GPUTextureUsage.RENDER_ATTACHMENT,
  });
  const querySet = device.createQuerySet({ type: 'timestamp', count: 4 });
  const resolve = device.createBuffer({ size: 32, usage: GPUBufferUsage.QUERY_RESOLVE | GPUBufferUsage.COPY_SRC });
  const read = device.createBuffer({ size: 32, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
  const lits: number[] = [];
  const shadows: number[] = [];
  for (let i = 0; i < repeats + 1; i++) {
    const enc = device.createCommandEncoder({ label: 'bench draw' });
    const sp = enc.beginRenderPass({
      label: 'bench shadow pass',
      colorAttachments: [],
      depthStencilAttachment: { view: shadowMap.createView(), depthClearValue: 1, depthLoadOp: 'clear', depthStoreOp: 'store' },
      timestampWrites: { querySet, beginningOfPassWriteIndex: 0, endOfPassWriteIndex: 1 },
    });
    sp.setPipeline(shadow);
    sp.setBindGroup(0, shadowGroup);
    sp.setVertexBuffer(0, mesh.positions);
    sp.setIndexBuffer(mesh.indices, 'uint32');
    sp.drawIndexedIndirect(mesh.drawArgs, 0);
    sp.end();
    const lp = enc.beginRenderPass({
      label: 'bench lit pass',
      colorAttachments: [{ view: color.createView(), clearValue: [0, 0, 0, 1], loadOp: 'clear', storeOp: 'store' }],
      depthStencilAttachment: { view: depth.createView(), depthClearValue: 1, depthLoadOp: 'clear', depthStoreOp: 'store' },
      timestampWrites: { querySet, beginningOfPassWriteIndex: 2, endOfPassWriteIndex: 3 },
    });
    lp.setPipeline(lit);
    lp.setBindGroup(0, litGroup);
    lp.setVertexBuffer(0, mesh.positions);
    lp.setVertexBuffer(1, mesh.normals);
    lp.setIndexBuffer(mesh.indices, 'uint32');
    lp.drawIndexedIndirect(mesh.drawArgs, 0);
    lp.end();
    enc.resolveQuerySet(querySet, 0, 4, resolve, 0);
    enc.copyBufferToBuffer(resolve, 0, read, 0, 32);
    device.queue.submit([enc.finish()]);
    await read.mapAsync(GPUMapMode.READ);
    const t = new BigUint64Array(read.getMappedRange().slice(0));
    read.unmap();
    if (i > 0) {
      shadows.push(Number(t[1] - t[0]) / 1e6);
      lits.push(Number(t[3] - t[2]) / 1e6);
    }
  }
  for (const x of [camera, lightCamera, resolve, read]) x.destroy();
  for (const x of [color, depth, shadowMap]) x.destroy();
  querySet.destroy();
  const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
  return { litMs: median(lits), shadowMs: median(shadows) };
}
