/**
 * Draws a stored, tessellated mesh (`TessellatedMesh`, see types.ts) every frame without
 * rebuilding it: the talk's point is to build the geometry once and draw it in every pass.
 *
 *   shadow pass   depth only, from an orthographic light fitted to the model's bounds
 *   main pass     backdrop, lit + shadowed mesh, ground, wireframe and cage overlays (4× MSAA)
 *
 * Both draw the mesh with drawIndexedIndirect(output.drawArgs), positions and normals bound as
 * vertex buffers, so the CPU never needs to know how many triangles the GPU produced. The
 * wireframe reads the same index and position buffers from storage. Patch colours (the NVIDIA
 * sample's "show irregular patches") read each vertex's source triangle (output.srcTri, from
 * storage by vertex index) and that triangle's kind (setPatchKinds). DOM-free: it takes a device,
 * a colour format, and a texture to draw into.
 *
 * The per-frame uniforms (SCENE_UNIFORMS) and the bind group layouts (RENDER_BIND_GROUPS,
 * RENDER_PIPELINE_GROUPS) are declared in contract/render.ts; every render shader is the generated
 * uniform declaration followed by its .wgsl files (RENDER_SHADERS, pipelines.ts, which creates
 * the pipelines); the timestamps' resources are render-timing.ts.
 */
import { HEAT_UNIFORMS, type HeatView } from '../acc/heat.ts';
import type { TessellatedMesh } from '../contract/tessellated-mesh.ts';
import type { CageLines } from './cage-mesh.ts';
import { MapStalled } from '../device/map-within.ts';
import { boundingSphere, DEFAULT_LIGHT_DIR, lightViewProj, type Bounds, type Vec3 } from './camera.ts';
import { MATERIALS, SCENE_UNIFORMS, type Material } from '../contract/render.ts';
import { createRenderPipelines, DEPTH_FORMAT } from './pipelines.ts';
import { createRenderTiming, type RenderTiming, TIMED_PASSES, TIMING_SLOTS } from './render-timing.ts';

export interface RendererOptions {
  /** Format of the views render() draws into (an -srgb format gives correct blending). */
  colorFormat: GPUTextureFormat;
  /** Enable per-pass GPU timing (the device must have 'timestamp-query'). */
  timestamps?: boolean;
  shadowMapSize?: number;
  sampleCount?: 1 | 4;
}

export interface View {
  /** Column-major view-projection, WebGPU clip space (z in 0..1). */
  viewProj: Float32Array;
  /** Model to world, a rotation (e.g. camera.ts upAxisMatrix). */
  model: Float32Array;
  eye: Vec3;
}

export interface DrawOptions {
  wireframe: boolean;
  cage: boolean;
  /** Tint the surface by the patch kind of each vertex's source triangle (see setPatchKinds). */
  patchColours?: boolean;
  /** Wireframe opacity, 0..1. */
  wireOpacity?: number;
  /** The surface's material under the studio rig: clay (the default) or metal. */
  material?: Material;
  /**
   * Split view: draw only the columns [x0, x1) of the target (fractions of its width), with the
   * same camera: the first region of a frame clears, a later one keeps what the earlier drew
   * (render() called once per region, each with its own shadow pass and, with timestamps, its
   * own timing slot: slot 1's passes are reported as 'shadow 2' and 'lit 2').
   */
  region?: { x0: number; x1: number; first: boolean; slot: 0 | 1 };
  /**
   * The ACC error views: colour the stored mesh by the values of setHeat (instead of its clay or
   * patch colours), `range` in the view's unit (fraction of the diagonal; degrees) drawn red.
   * Ignored without values or while a SurfaceDrawer draws.
   */
  heat?: { view: HeatView; range: number } | null;
}

/**
 * Something that draws the surface itself in the shadow and lit passes instead of the stored
 * mesh: the instanced tessellator (src/gpu/instanced/instanced.ts), which evaluates the surface again in
 * every pass. It may set any bind group and pipeline; the renderer sets its own again after.
 */
export interface SurfaceDrawer {
  drawShadow(pass: GPURenderPassEncoder, closed: boolean): void;
  drawLit(pass: GPURenderPassEncoder, closed: boolean): void;
  drawWire(pass: GPURenderPassEncoder): void;
}

/** What a SurfaceDrawer binds to shade as the renderer does (Renderer.shadingResources). */
export interface ShadingResources {
  /** The per-frame uniforms (SCENE_UNIFORMS). */
  scene: GPUBuffer;
  shadowMap: GPUTextureView;
  shadowSampler: GPUSampler;
  colorFormat: GPUTextureFormat;
  depthFormat: GPUTextureFormat;
  sampleCount: number;
}

/** The patch colours (declared in contract/render.ts, where the lit shader's palette comes from too). */
export { PATCH_COLOURS } from '../contract/render.ts';

export class Renderer {
  readonly device: GPUDevice;
  readonly colorFormat: GPUTextureFormat;
  readonly sampleCount: number;
  readonly shadowMapSize: number;
  /**
   * Whether the vertex stage may read storage buffers: always in core WebGPU; in compatibility
   * mode only where maxStorageBuffersInVertexStage allows (its default is 0). The wireframe, the
   * patch colours and the heat maps read per-vertex data from storage by vertex index; without it
   * they are not drawn (render() ignores those options) and the lit pass draws its plain colours
   * through a vertex stage that reads vertex buffers only (litVertexPlain).
   */
  readonly vertexStorage: boolean;

  #sceneBuffer: GPUBuffer;
  #sceneData = new DataView(new ArrayBuffer(SCENE_UNIFORMS.size));
  #sceneBindGroup: GPUBindGroup;
  #shadingBindGroup: GPUBindGroup;
  #shadowMap: GPUTexture;
  #shadowSampler: GPUSampler;
  #drawer: SurfaceDrawer | null = null;

  /** [open, closed] (setMesh's `closed`). */
  #shadowPipelines: GPURenderPipeline[] = [];
  /** [front faces, back faces]: a closed surface draws the first, an open one both (pipelines.ts says why). */
  #litPipelines: GPURenderPipeline[] = [];
  #closed = false;
  #groundPipeline: GPURenderPipeline;
  #backdropPipeline: GPURenderPipeline;
  /** Made when first drawn with (pipelines.ts RenderPipelines). */
  #wirePipeline: () => GPURenderPipeline | null;
  #wireArgsPipeline: () => GPUComputePipeline;
  #cageHiddenPipeline: () => GPURenderPipeline;
  #cageVisiblePipeline: () => GPURenderPipeline;
  /** Two read-only storage buffers for the vertex stage: the wireframe's indices and positions,
   * and the patch colours' source triangles and kinds share it. */
  #vertexStorageLayout: GPUBindGroupLayout | null = null;
  #wireArgsLayout: GPUBindGroupLayout;
  /** One u32 kind per source triangle (a single 0 when there are none). */
  #patchKinds: GPUBuffer;
  #patchBindGroup: GPUBindGroup | null = null;
  /** The heat map (src/gpu/acc/heat.ts): [front faces, back faces] pipelines as the lit ones,
   * its layout, uniforms and the bind group of the values set (null: none). */
  #heatPipeline: (back: boolean) => GPURenderPipeline | null;
  #heatLayout: GPUBindGroupLayout | null = null;
  #heatUniforms: GPUBuffer;
  #heatData = new DataView(new ArrayBuffer(HEAT_UNIFORMS.size));
  #heatBindGroup: GPUBindGroup | null = null;

  #wireArgs: GPUBuffer;
  #mesh: TessellatedMesh | null = null;
  #wireBindGroup: GPUBindGroup | null = null;
  #wireArgsBindGroup: GPUBindGroup | null = null;
  #cage: CageLines | null = null;

  #bounds: Bounds = { min: [-1, -1, -1], max: [1, 1, 1] };
  #lightViewProj = new Float32Array(16);

  #msaaTexture: GPUTexture | null = null;
  #depthTexture: GPUTexture | null = null;

  #timingStalled = false;
  /** The timestamps' readback never settled (src/gpu/device/map-within.ts): timing is off for good. */
  get timingStalled(): boolean {
    return this.#timingStalled;
  }

  #timing: RenderTiming | null = null;

  static create(device: GPUDevice, options: RendererOptions): Renderer {
    return new Renderer(device, options);
  }

  private constructor(device: GPUDevice, options: RendererOptions) {
    this.device = device;
    this.colorFormat = options.colorFormat;
    this.sampleCount = options.sampleCount ?? 4;
    this.shadowMapSize = options.shadowMapSize ?? 2048;
    this.vertexStorage = vertexStorageBuffers(device) >= 2;

    this.#sceneBuffer = device.createBuffer({
      label: 'scene uniforms',
      size: SCENE_UNIFORMS.size,
      usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST,
    });
    this.#shadowMap = device.createTexture({
      label: 'shadow map',
      size: [this.shadowMapSize, this.shadowMapSize],
      format: DEPTH_FORMAT,
      usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.TEXTURE_BINDING,
    });
    // Hardware PCF: a linear comparison sampler blends four depth tests per tap.
    const shadowSampler = (this.#shadowSampler = device.createSampler({
      label: 'shadow comparison sampler',
      compare: 'less-equal',
      magFilter: 'linear',
      minFilter: 'linear',
    }));
    this.#wireArgs = device.createBuffer({
      label: 'wireframe draw args',
      size: 16,
      usage: GPUBufferUsage.INDIRECT | GPUBufferUsage.STORAGE,
    });

    const pipelines = createRenderPipelines(device, this.colorFormat, this.sampleCount, this.vertexStorage);
    const layouts = pipelines.layouts;
    this.#vertexStorageLayout = layouts.vertexStorage ?? null;
    this.#wireArgsLayout = layouts.wireArgs;
    this.#patchKinds = device.createBuffer({
      label: 'patch kinds (none)',
      size: 4,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
    });
    this.#sceneBindGroup = device.createBindGroup({
      label: 'scene bind group',
      layout: layouts.scene,
      entries: [{ binding: 0, resource: { buffer: this.#sceneBuffer } }],
    });
    this.#shadingBindGroup = device.createBindGroup({
      label: 'shading bind group',
      layout: layouts.shading,
      entries: [
        { binding: 0, resource: this.#shadowMap.createView({ label: 'shadow map view' }) },
        { binding: 1, resource: shadowSampler },
      ],
    });

    this.#heatUniforms = device.createBuffer({
      label: 'heat uniforms',
      size: HEAT_UNIFORMS.size,
      usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST,
    });
    this.#heatLayout = pipelines.heatGroupLayout;
    this.#shadowPipelines = pipelines.shadow;
    this.#litPipelines = pipelines.lit;
    this.#heatPipeline = pipelines.heat;
    this.#groundPipeline = pipelines.ground;
    this.#backdropPipeline = pipelines.backdrop;
    this.#wirePipeline = pipelines.wire;
    this.#wireArgsPipeline = pipelines.wireArgs;
    this.#cageHiddenPipeline = pipelines.cageHidden;
    this.#cageVisiblePipeline = pipelines.cageVisible;

    if (options.timestamps) this.#timing = createRenderTiming(device);
  }

  /** The mesh to draw: the tessellator's output (its buffers live as long as it does) or the cage's.
   * `closed`: its cage has no boundary (mesh/topology.ts isClosed), so back faces are culled. */
  setMesh(mesh: TessellatedMesh | null, closed = false): void {
    this.#mesh = mesh;
    this.#closed = closed;
    this.#wireBindGroup = null;
    this.#wireArgsBindGroup = null;
    this.#patchBindGroup = null;
    if (!mesh || !this.#vertexStorageLayout) return;
    this.#bindPatches();
    this.#wireBindGroup = this.device.createBindGroup({
      label: 'wireframe bind group',
      layout: this.#vertexStorageLayout,
      entries: [
        { binding: 0, resource: { buffer: mesh.indices } },
        { binding: 1, resource: { buffer: mesh.positions } },
      ],
    });
    this.#wireArgsBindGroup = this.device.createBindGroup({
      label: 'wireframe args bind group',
      layout: this.#wireArgsLayout,
      entries: [
        { binding: 0, resource: { buffer: mesh.drawArgs, size: 20 } },
        { binding: 1, resource: { buffer: this.#wireArgs } },
      ],
    });
  }

  /**
   * The patch kind of each source triangle of the mesh (src/gpu/cc/build.ts CatmullClarkData.triKind:
   * 0 regular, 1 irregular quad, 2 triangle region, 3 crease), for patch colours; null for none
   * (the surface is then drawn in its usual colours even with patchColours on).
   */
  setPatchKinds(kinds: ArrayLike<number> | null): void {
    this.#patchKinds.destroy();
    const n = kinds?.length ?? 0;
    this.#patchKinds = this.device.createBuffer({
      label: n ? 'patch kinds' : 'patch kinds (none)',
      size: 4 * Math.max(1, n),
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
    });
    // Kinds are offset by one on the GPU: 0 means "no kind", drawn in the usual colours.
    if (kinds && n) {
      // A plain loop: Uint32Array.from with a map function took 14 ms for 80,000 triangles.
      const words = new Uint32Array(n);
      for (let i = 0; i < n; i++) words[i] = kinds[i] + 1;
      this.device.queue.writeBuffer(this.#patchKinds, 0, words);
    }
    this.#bindPatches();
  }

  #bindPatches(): void {
    const mesh = this.#mesh;
    this.#patchBindGroup =
      mesh && this.#vertexStorageLayout
        ? this.device.createBindGroup({
            label: 'patch colours bind group',
            layout: this.#vertexStorageLayout,
            entries: [
              { binding: 0, resource: { buffer: mesh.srcTri } },
              { binding: 1, resource: { buffer: this.#patchKinds } },
            ],
          })
        : null;
  }

  /**
   * The heat map's values: 2 f32 per output vertex of the mesh (src/gpu/acc/heat.ts
   * AccHeatPass.values), read by vertex index; null for none (DrawOptions.heat then draws the
   * usual colours). Set again after setMesh when the mesh changes.
   */
  setHeat(values: GPUBufferBinding | null): void {
    this.#heatBindGroup =
      values && this.#heatLayout
        ? this.device.createBindGroup({
            label: 'heat bind group',
            layout: this.#heatLayout,
            entries: [
              { binding: 0, resource: values },
              { binding: 1, resource: { buffer: this.#heatUniforms } },
            ],
          })
        : null;
  }

  /** Draw the surface with `drawer` (in the shadow, lit and wireframe passes) instead of the
   * stored mesh (setMesh); null: the stored mesh again. */
  setDrawer(drawer: SurfaceDrawer | null): void {
    this.#drawer = drawer;
  }

  /** The scene uniform, shadow map and formats a SurfaceDrawer shades with. */
  get shadingResources(): ShadingResources {
    return {
      scene: this.#sceneBuffer,
      shadowMap: this.#shadowMap.createView({ label: 'shadow map view (surface drawer)' }),
      shadowSampler: this.#shadowSampler,
      colorFormat: this.colorFormat,
      depthFormat: DEPTH_FORMAT,
      sampleCount: this.sampleCount,
    };
  }

  /** The cage overlay's lines (the renderer does not own them). */
  setCage(cage: CageLines | null): void {
    this.#cage = cage;
  }

  /**
   * The model's bounds in world space (the cage's are conservative: the limit surface lies
   * inside its hull): they fit the light's box and place the ground.
   */
  setBounds(bounds: Bounds): void {
    this.#bounds = bounds;
    this.#lightViewProj.set(lightViewProj(boundingSphere(bounds), DEFAULT_LIGHT_DIR));
  }

  /** Encode the shadow and main passes, drawing into `target` (any size; attachments follow it). */
  render(encoder: GPUCommandEncoder, target: GPUTexture, view: View, options: DrawOptions): void {
    this.#ensureAttachments(target.width, target.height);
    this.#writeScene(view, target.width, target.height, options);
    const drawer = this.#drawer;
    const mesh = drawer ? null : this.#mesh;
    // Once the timestamps' map stalled (mapWithin), no pass writes timestamps any more.
    const timing = this.#timingStalled ? null : this.#timing;

    if (mesh && options.wireframe && this.#wireArgsBindGroup) {
      // Tracks whatever index count the tessellator last wrote, at the cost of one thread.
      const pass = encoder.beginComputePass({ label: 'wireframe args pass' });
      pass.setPipeline(this.#wireArgsPipeline());
      pass.setBindGroup(0, this.#wireArgsBindGroup);
      pass.dispatchWorkgroups(1);
      pass.end();
    }

    const region = options.region;
    const slot = region?.slot ?? 0;
    const q = TIMED_PASSES.length * 2 * slot;
    const shadowPass = encoder.beginRenderPass({
      label: 'shadow pass',
      colorAttachments: [],
      depthStencilAttachment: {
        view: this.#shadowMap.createView({ label: 'shadow map attachment' }),
        depthClearValue: 1,
        depthLoadOp: 'clear',
        depthStoreOp: 'store',
      },
      timestampWrites: timing ? { querySet: timing.querySet, beginningOfPassWriteIndex: q, endOfPassWriteIndex: q + 1 } : undefined,
    });
    if (drawer) drawer.drawShadow(shadowPass, this.#closed);
    if (mesh) {
      shadowPass.setPipeline(this.#shadowPipelines[+this.#closed]);
      shadowPass.setBindGroup(0, this.#sceneBindGroup);
      shadowPass.setVertexBuffer(0, mesh.positions);
      shadowPass.setIndexBuffer(mesh.indices, 'uint32');
      shadowPass.drawIndexedIndirect(mesh.drawArgs, 0);
    }
    shadowPass.end();

    const msaa = this.sampleCount > 1;
    const targetView = target.createView({ label: 'render target view', format: this.colorFormat });
    const pass = encoder.beginRenderPass({
      label: 'lit pass',
      colorAttachments: [
        {
          view: msaa ? this.#msaaTexture!.createView({ label: 'msaa colour view' }) : targetView,
          resolveTarget: msaa ? targetView : undefined,
          clearValue: [0, 0, 0, 1],
          // A later region of a split view draws over what the earlier ones left.
          loadOp: region && !region.first ? 'load' : 'clear',
          // The multisampled colour is only needed until it is resolved (a split view's next
          // region loads it: it resolves the whole attachment again).
          storeOp: msaa && !region ? 'discard' : 'store',
        },
      ],
      depthStencilAttachment: {
        view: this.#depthTexture!.createView({ label: 'depth view' }),
        depthClearValue: 1,
        depthLoadOp: 'clear',
        depthStoreOp: 'discard',
      },
      timestampWrites: timing ? { querySet: timing.querySet, beginningOfPassWriteIndex: q + 2, endOfPassWriteIndex: q + 3 } : undefined,
    });
    if (region) {
      const x0 = Math.round(region.x0 * target.width),
        x1 = Math.round(region.x1 * target.width);
      pass.setScissorRect(x0, 0, Math.max(0, x1 - x0), target.height);
    }
    pass.setBindGroup(0, this.#sceneBindGroup);
    pass.setBindGroup(1, this.#shadingBindGroup);
    pass.setPipeline(this.#backdropPipeline);
    pass.draw(3);
    const heat = mesh && options.heat && this.#heatBindGroup ? options.heat : null;
    if (heat) {
      HEAT_UNIFORMS.write(this.#heatData, { view: heat.view === 'normal' ? 1 : 0, range: heat.range });
      this.device.queue.writeBuffer(this.#heatUniforms, 0, this.#heatData.buffer);
    }
    if (mesh && (heat || this.#patchBindGroup || !this.vertexStorage)) {
      if (this.vertexStorage) pass.setBindGroup(2, heat ? this.#heatBindGroup : this.#patchBindGroup);
      pass.setVertexBuffer(0, mesh.positions);
      pass.setVertexBuffer(1, mesh.normals);
      pass.setIndexBuffer(mesh.indices, 'uint32');
      for (const back of this.#closed ? [false] : [false, true]) {
        const pipeline = heat ? this.#heatPipeline(back) : this.#litPipelines[+back];
        if (!pipeline) continue;
        pass.setPipeline(pipeline);
        pass.drawIndexedIndirect(mesh.drawArgs, 0);
      }
    }
    if (drawer) {
      drawer.drawLit(pass, this.#closed);
      pass.setBindGroup(0, this.#sceneBindGroup);
      pass.setBindGroup(1, this.#shadingBindGroup);
    }
    pass.setPipeline(this.#groundPipeline);
    pass.draw(4);
    const wirePipeline = mesh && options.wireframe && this.#wireBindGroup ? this.#wirePipeline() : null;
    if (wirePipeline) {
      pass.setPipeline(wirePipeline);
      pass.setBindGroup(1, this.#wireBindGroup);
      pass.drawIndirect(this.#wireArgs, 0);
    }
    if (drawer && options.wireframe) {
      drawer.drawWire(pass);
      pass.setBindGroup(0, this.#sceneBindGroup);
    }
    const cage = this.#cage;
    if (cage && options.cage && cage.vertexCount > 0) {
      pass.setVertexBuffer(0, cage.vertices);
      pass.setPipeline(this.#cageHiddenPipeline());
      pass.draw(cage.vertexCount);
      pass.setPipeline(this.#cageVisiblePipeline());
      pass.draw(cage.vertexCount);
    }
    pass.end();

    if (timing) {
      const n = TIMED_PASSES.length * 2;
      encoder.resolveQuerySet(timing.querySet, q, n, timing.resolve, 256 * slot);
      // Into a free readback buffer of the ring; a split view copies after its last region (slot 1).
      const read = !region || slot === TIMING_SLOTS - 1 ? timing.ring.acquire(region ? TIMING_SLOTS : 1) : null;
      if (read)
        for (let k = 0; k < TIMING_SLOTS; k++) encoder.copyBufferToBuffer(timing.resolve, 256 * k, read as GPUBuffer, 8 * n * k, 8 * n);
    }
  }

  /**
   * Milliseconds per pass ({ shadow, lit }) of the latest frame whose timestamps have come back;
   * {} without 'timestamp-query'. Call after submitting the frame that render() encoded.
   */
  async readTimings(): Promise<Record<string, number>> {
    const timing = this.#timing;
    if (!timing) return {};
    try {
      const got = await timing.ring.readLatest();
      if (got) {
        const out: Record<string, number> = {};
        for (let slot = 0; slot < got.meta; slot++)
          TIMED_PASSES.forEach((name, i) => {
            const k = TIMED_PASSES.length * slot + i;
            const ns = Number(got.ticks[2 * k + 1] - got.ticks[2 * k]);
            // Timestamps may be quantized or reordered; a negative span means "unknown".
            if (ns >= 0) out[slot ? `${name} 2` : name] = ns / 1e6;
          });
        timing.last = out;
      }
    } catch (err) {
      // A map that never settled: stop timing (the stats say so). Else the device was lost or
      // destroyed while mapping: keep the last numbers.
      if (err instanceof MapStalled) this.#timingStalled = true;
    }
    return { ...timing.last };
  }

  /** A frame's timestamps wait to be read (it was drawn while the last read was in flight). */
  get timingUnread(): boolean {
    return this.#timing?.ring.unread ?? false;
  }

  destroy(): void {
    this.#sceneBuffer.destroy();
    this.#shadowMap.destroy();
    this.#wireArgs.destroy();
    this.#patchKinds.destroy();
    this.#heatUniforms.destroy();
    this.#msaaTexture?.destroy();
    this.#depthTexture?.destroy();
    if (this.#timing) {
      this.#timing.querySet.destroy();
      this.#timing.resolve.destroy();
      this.#timing.ring.destroy();
    }
  }

  #ensureAttachments(width: number, height: number): void {
    const depth = this.#depthTexture;
    if (depth && depth.width === width && depth.height === height) return;
    this.#msaaTexture?.destroy();
    this.#depthTexture?.destroy();
    this.#msaaTexture =
      this.sampleCount > 1
        ? this.device.createTexture({
            label: 'msaa colour target',
            size: [width, height],
            format: this.colorFormat,
            sampleCount: this.sampleCount,
            usage: GPUTextureUsage.RENDER_ATTACHMENT,
          })
        : null;
    this.#depthTexture = this.device.createTexture({
      label: 'depth target',
      size: [width, height],
      format: DEPTH_FORMAT,
      sampleCount: this.sampleCount,
      usage: GPUTextureUsage.RENDER_ATTACHMENT,
    });
  }

  #writeScene(view: View, width: number, height: number, options: DrawOptions): void {
    const sphere = boundingSphere(this.#bounds);
    SCENE_UNIFORMS.write(this.#sceneData, {
      viewProj: view.viewProj,
      lightViewProj: this.#lightViewProj,
      model: view.model,
      eye: [...view.eye, sphere.radius],
      toLight: [...DEFAULT_LIGHT_DIR, 1 / this.shadowMapSize],
      // The ground sits at the cage's lowest point, a hair lower so it never z-fights the surface.
      center: [...sphere.center, this.#bounds.min[1] - sphere.radius * 1e-3],
      viewport: [width, height, options.wireOpacity ?? 0.45, options.patchColours ? 1 : 0],
      look: [MATERIALS.indexOf(options.material ?? 'clay'), 0, 0, 0],
    });
    this.device.queue.writeBuffer(this.#sceneBuffer, 0, this.#sceneData.buffer);
  }
}

/** Storage buffers the vertex stage may read: the compatibility-mode limit where the
 * implementation has it (older ones do not, and are all core: the per-stage limit then). */
export function vertexStorageBuffers(device: GPUDevice): number {
  const limits = device.limits as GPUSupportedLimits & { maxStorageBuffersInVertexStage?: number };
  return limits.maxStorageBuffersInVertexStage ?? limits.maxStorageBuffersPerShaderStage;
}
