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
 * uniform declaration followed by its .wgsl files (RENDER_SHADERS).
 */
import commonWGSL from '../../../wgsl/render/common.wgsl?raw';
import shadingWGSL from '../../../wgsl/render/shading.wgsl?raw';
import shadowWGSL from '../../../wgsl/render/shadow.wgsl?raw';
import litWGSL from '../../../wgsl/render/lit.wgsl?raw';
import groundWGSL from '../../../wgsl/render/ground.wgsl?raw';
import backdropWGSL from '../../../wgsl/render/backdrop.wgsl?raw';
import wireArgsWGSL from '../../../wgsl/render/wire-args.wgsl?raw';
import wireLinesWGSL from '../../../wgsl/render/wire-lines.wgsl?raw';
import wireCageWGSL from '../../../wgsl/render/wire-cage.wgsl?raw';
import heatWGSL from '../../../wgsl/render/heat.wgsl?raw';
import { HEAT_BIND_GROUP, HEAT_UNIFORMS, heatRenderWgsl, type HeatView } from '../acc/heat.ts';
import type { TessellatedMesh } from '../contract/tessellated-mesh.ts';
import { CAGE_LINE_STRIDE, type CageLines } from './cage-mesh.ts';
import { mapWithin, MapStalled, TIMING_MAP_DEADLINE_MS } from '../device/map-within.ts';
import { boundingSphere, DEFAULT_LIGHT_DIR, lightViewProj, type Bounds, type Vec3 } from './camera.ts';
import {
  RENDER_BIND_GROUPS,
  RENDER_PIPELINE_GROUPS,
  SCENE_UNIFORMS,
  type RenderBindGroup,
  type RenderPipelineName,
} from '../contract/render.ts';
import { sceneWgsl } from '../contract/contract.ts';

/** The WGSL sources of each pipeline's shader module, in order (the two cage pipelines share one). */
export const RENDER_SHADERS: Record<RenderPipelineName, readonly string[]> = {
  shadow: [sceneWgsl, commonWGSL, shadowWGSL],
  lit: [sceneWgsl, commonWGSL, shadingWGSL, litWGSL],
  ground: [sceneWgsl, commonWGSL, shadingWGSL, groundWGSL],
  backdrop: [sceneWgsl, commonWGSL, backdropWGSL],
  wireframe: [sceneWgsl, commonWGSL, wireLinesWGSL],
  cage: [sceneWgsl, commonWGSL, wireCageWGSL],
  wireArgs: [wireArgsWGSL],
};

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

const DEPTH_FORMAT: GPUTextureFormat = 'depth32float';
/** An open surface's back faces are drawn this far behind its front faces (depthBias, in the
 * depth format's units, and depthBiasSlopeScale): see the lit pipelines. */
const BACK_FACE_DEPTH_BIAS = 4;
const BACK_FACE_DEPTH_SLOPE = 4.0;

/** The primitive and depth states of a lit (or heat) draw of a mesh's front or back faces: the
 * back faces' draw is depth-biased behind the front faces' (the lit pipelines say why). The
 * instanced tessellator's drawer uses the same. */
export function meshFaceStates(
  back: boolean,
  depthFormat: GPUTextureFormat,
): { primitive: GPUPrimitiveState; depthStencil: GPUDepthStencilState } {
  return {
    primitive: { topology: 'triangle-list', cullMode: back ? 'front' : 'back', frontFace: 'ccw' },
    depthStencil: {
      format: depthFormat,
      depthWriteEnabled: true,
      depthCompare: 'less',
      ...(back ? { depthBias: BACK_FACE_DEPTH_BIAS, depthBiasSlopeScale: BACK_FACE_DEPTH_SLOPE } : {}),
    },
  };
}
/** Vertex buffers of the mesh: positions then normals, float32x3, tightly packed. */
const MESH_BUFFERS: GPUVertexBufferLayout[] = [
  { arrayStride: 12, attributes: [{ shaderLocation: 0, offset: 0, format: 'float32x3' }] },
  { arrayStride: 12, attributes: [{ shaderLocation: 1, offset: 0, format: 'float32x3' }] },
];
const TIMED_PASSES = ['shadow', 'lit'] as const;
/** Timing slots: one per region of a split view (DrawOptions.region.slot). */
const TIMING_SLOTS = 2;

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
  /** [front faces, back faces]: a closed surface draws the first, an open one both (below). */
  #litPipelines: GPURenderPipeline[] = [];
  #closed = false;
  #groundPipeline: GPURenderPipeline;
  #backdropPipeline: GPURenderPipeline;
  #wirePipeline: GPURenderPipeline | null = null;
  #wireArgsPipeline: GPUComputePipeline;
  #cageHiddenPipeline: GPURenderPipeline;
  #cageVisiblePipeline: GPURenderPipeline;
  /** Two read-only storage buffers for the vertex stage: the wireframe's indices and positions,
   * and the patch colours' source triangles and kinds share it. */
  #vertexStorageLayout: GPUBindGroupLayout | null = null;
  #wireArgsLayout: GPUBindGroupLayout;
  /** One u32 kind per source triangle (a single 0 when there are none). */
  #patchKinds: GPUBuffer;
  #patchBindGroup: GPUBindGroup | null = null;
  /** The heat map (src/gpu/acc/heat.ts): [front faces, back faces] pipelines as the lit ones,
   * its layout, uniforms and the bind group of the values set (null: none). */
  #heatPipelines: GPURenderPipeline[] = [];
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

  #timing: {
    querySet: GPUQuerySet;
    resolve: GPUBuffer;
    read: GPUBuffer;
    state: 'idle' | 'copied' | 'mapping';
    last: Record<string, number>;
    /** The slots the copied frame wrote. */
    slots: number;
  } | null = null;

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

    const layouts = {} as Record<RenderBindGroup, GPUBindGroupLayout>;
    for (const [name, entries] of Object.entries(RENDER_BIND_GROUPS) as [RenderBindGroup, readonly GPUBindGroupLayoutEntry[]][]) {
      // A vertex-visible storage layout is itself invalid where the vertex stage has none.
      if (name === 'vertexStorage' && !this.vertexStorage) continue;
      layouts[name] = device.createBindGroupLayout({ label: `${name} bind group layout`, entries: [...entries] });
    }
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

    const pipelineLayout = (name: RenderPipelineName) =>
      device.createPipelineLayout({
        label: `${name} pipeline layout`,
        // Without vertex-stage storage the lit pipeline has no patch-colour group (litVertexPlain).
        bindGroupLayouts: RENDER_PIPELINE_GROUPS[name].filter((g) => layouts[g]).map((g) => layouts[g]),
      });
    const module = (name: RenderPipelineName) =>
      device.createShaderModule({ label: `${name} shader`, code: RENDER_SHADERS[name].join('\n') });
    const shadowModule = module('shadow');
    const litModule = module('lit');
    const groundModule = module('ground');
    const backdropModule = module('backdrop');
    const wireModule = this.vertexStorage ? module('wireframe') : null;
    const cageModule = module('cage');
    const wireArgsModule = module('wireArgs');

    if (this.vertexStorage)
      this.#heatLayout = device.createBindGroupLayout({ label: 'heat bind group layout', entries: [...HEAT_BIND_GROUP] });
    this.#heatUniforms = device.createBuffer({
      label: 'heat uniforms',
      size: HEAT_UNIFORMS.size,
      usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST,
    });
    // The lit pipeline's groups with the heat group in place of the patch colours' (group 2).
    const heatLayout = this.#heatLayout
      ? device.createPipelineLayout({
          label: 'heat pipeline layout',
          bindGroupLayouts: [layouts.scene, layouts.shading, this.#heatLayout],
        })
      : null;
    const heatModule = device.createShaderModule({
      label: 'heat shader',
      code: [sceneWgsl, commonWGSL, heatRenderWgsl, heatWGSL].join('\n'),
    });

    const multisample = { count: this.sampleCount };
    const blend: GPUBlendState = {
      color: { srcFactor: 'src-alpha', dstFactor: 'one-minus-src-alpha', operation: 'add' },
      alpha: { srcFactor: 'one', dstFactor: 'one-minus-src-alpha', operation: 'add' },
    };
    const opaqueTarget = [{ format: this.colorFormat }];
    const blendedTarget = [{ format: this.colorFormat, blend }];
    // Overlays test against the mesh's depth but never write it.
    const overlayDepth = (compare: GPUCompareFunction): GPUDepthStencilState => ({
      format: DEPTH_FORMAT,
      depthWriteEnabled: false,
      depthCompare: compare,
    });

    // The shadow pipeline twice, by the mesh's cage (setMesh): an open surface casts from both
    // faces; a closed one's shadow map keeps the faces turned AWAY from the light: the lit side
    // then never shadows itself (culling those back faces there drew acne stripes all over the
    // lit side).
    for (const closed of [false, true]) {
      this.#shadowPipelines[+closed] = device.createRenderPipeline({
        label: closed ? 'shadow pipeline (closed: faces towards the light culled)' : 'shadow pipeline (open: two-sided)',
        layout: pipelineLayout('shadow'),
        vertex: { module: shadowModule, entryPoint: 'shadowVertex', buffers: [MESH_BUFFERS[0]] },
        primitive: { topology: 'triangle-list', cullMode: closed ? 'front' : 'none', frontFace: 'ccw' },
        // Slope-scaled bias against acne on surfaces the light grazes.
        depthStencil: { format: DEPTH_FORMAT, depthWriteEnabled: true, depthCompare: 'less', depthBias: 2, depthBiasSlopeScale: 2.0 },
      });
    }
    // The lit and heat pipelines by the faces they draw. A closed surface draws its front faces
    // only: its back faces would fight them along occlusion contours (the dotted brow of issue
    // 13) and show where a thin sliver folds. An open surface also draws its back faces (lit from
    // the side seen, wgsl/render/lit.wgsl), in a second draw pushed back by a slope-scaled depth bias:
    // at an occlusion contour the tessellation folds over by a fraction of a pixel, the two
    // sheets there lie at one depth and steep, and the bias lets the front sheet win, where one
    // depth test for both drew the back sheet's inside as dark dots along the contour. An inside
    // seen through an opening has no front face near it in depth, so it shows as before.
    for (const back of [false, true]) {
      const side = back ? 'back faces, depth-biased behind the front faces' : 'front faces';
      const { primitive, depthStencil } = meshFaceStates(back, DEPTH_FORMAT);
      this.#litPipelines[+back] = device.createRenderPipeline({
        label: `lit pipeline (${side})`,
        layout: pipelineLayout('lit'),
        vertex: { module: litModule, entryPoint: this.vertexStorage ? 'litVertex' : 'litVertexPlain', buffers: MESH_BUFFERS },
        fragment: { module: litModule, entryPoint: 'litFragment', targets: opaqueTarget },
        primitive,
        depthStencil,
        multisample,
      });
      if (!heatLayout) continue;
      this.#heatPipelines[+back] = device.createRenderPipeline({
        label: `heat pipeline (${side})`,
        layout: heatLayout,
        vertex: { module: heatModule, entryPoint: 'heatVertex', buffers: MESH_BUFFERS },
        fragment: { module: heatModule, entryPoint: 'heatFragment', targets: opaqueTarget },
        primitive,
        depthStencil,
        multisample,
      });
    }
    this.#groundPipeline = device.createRenderPipeline({
      label: 'ground pipeline',
      layout: pipelineLayout('ground'),
      vertex: { module: groundModule, entryPoint: 'groundVertex' },
      fragment: { module: groundModule, entryPoint: 'groundFragment', targets: blendedTarget },
      primitive: { topology: 'triangle-strip', cullMode: 'none' },
      depthStencil: overlayDepth('less'),
      multisample,
    });
    this.#backdropPipeline = device.createRenderPipeline({
      label: 'backdrop pipeline',
      layout: pipelineLayout('backdrop'),
      vertex: { module: backdropModule, entryPoint: 'backdropVertex' },
      fragment: { module: backdropModule, entryPoint: 'backdropFragment', targets: opaqueTarget },
      primitive: { topology: 'triangle-list' },
      depthStencil: overlayDepth('always'),
      multisample,
    });
    if (wireModule)
      this.#wirePipeline = device.createRenderPipeline({
        label: 'wireframe pipeline',
        layout: pipelineLayout('wireframe'),
        vertex: { module: wireModule, entryPoint: 'wireVertex' },
        fragment: { module: wireModule, entryPoint: 'wireFragment', targets: blendedTarget },
        primitive: { topology: 'line-list' },
        depthStencil: overlayDepth('less-equal'),
        multisample,
      });
    const cageLayout = pipelineLayout('cage');
    const cagePipeline = (label: string, opacity: number, compare: GPUCompareFunction) =>
      device.createRenderPipeline({
        label,
        layout: cageLayout,
        vertex: {
          module: cageModule,
          entryPoint: 'cageVertex',
          buffers: [
            {
              arrayStride: CAGE_LINE_STRIDE,
              attributes: [
                { shaderLocation: 0, offset: 0, format: 'float32x3' },
                { shaderLocation: 1, offset: 12, format: 'unorm8x4' },
              ],
            },
          ],
        },
        fragment: { module: cageModule, entryPoint: 'cageFragment', targets: blendedTarget, constants: { OPACITY: opacity } },
        primitive: { topology: 'line-list' },
        depthStencil: overlayDepth(compare),
        multisample,
      });
    // The cage mostly floats outside the limit surface; where it dips behind, show it as a ghost.
    this.#cageHiddenPipeline = cagePipeline('cage overlay (hidden part) pipeline', 0.22, 'greater');
    this.#cageVisiblePipeline = cagePipeline('cage overlay pipeline', 1.0, 'less-equal');
    this.#wireArgsPipeline = device.createComputePipeline({
      label: 'wireframe args pipeline',
      layout: pipelineLayout('wireArgs'),
      compute: { module: wireArgsModule, entryPoint: 'wireArgsMain' },
    });

    if (options.timestamps) {
      const count = TIMED_PASSES.length * 2 * TIMING_SLOTS;
      this.#timing = {
        querySet: device.createQuerySet({ label: 'render timestamps', type: 'timestamp', count }),
        // One 256-byte-aligned block per slot (resolveQuerySet's destination offset must be).
        resolve: device.createBuffer({
          label: 'render timestamps resolve',
          size: 256 * (TIMING_SLOTS - 1) + 8 * TIMED_PASSES.length * 2,
          usage: GPUBufferUsage.QUERY_RESOLVE | GPUBufferUsage.COPY_SRC,
        }),
        read: device.createBuffer({
          label: 'render timestamps readback',
          size: count * 8,
          usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
        }),
        state: 'idle',
        last: {},
        slots: 1,
      };
    }
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
    if (kinds && n)
      this.device.queue.writeBuffer(
        this.#patchKinds,
        0,
        Uint32Array.from(kinds, (k) => k + 1),
      );
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
    this.#writeScene(view, target.width, target.height, options.wireOpacity ?? 0.45, options.patchColours ?? false);
    const drawer = this.#drawer;
    const mesh = drawer ? null : this.#mesh;
    // Once the timestamps' map stalled (mapWithin), no pass writes timestamps any more.
    const timing = this.#timingStalled ? null : this.#timing;

    if (mesh && options.wireframe && this.#wireArgsBindGroup) {
      // Tracks whatever index count the tessellator last wrote, at the cost of one thread.
      const pass = encoder.beginComputePass({ label: 'wireframe args pass' });
      pass.setPipeline(this.#wireArgsPipeline);
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
        pass.setPipeline(heat ? this.#heatPipelines[+back] : this.#litPipelines[+back]);
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
    if (mesh && options.wireframe && this.#wireBindGroup && this.#wirePipeline) {
      pass.setPipeline(this.#wirePipeline);
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
      pass.setPipeline(this.#cageHiddenPipeline);
      pass.draw(cage.vertexCount);
      pass.setPipeline(this.#cageVisiblePipeline);
      pass.draw(cage.vertexCount);
    }
    pass.end();

    if (timing) {
      const n = TIMED_PASSES.length * 2;
      encoder.resolveQuerySet(timing.querySet, q, n, timing.resolve, 256 * slot);
      // Copy only into an idle readback buffer: a mapped or mapping one cannot be written; a
      // split view copies after its last region (slot 1).
      if (timing.state === 'idle' && (!region || slot === TIMING_SLOTS - 1)) {
        for (let k = 0; k < TIMING_SLOTS; k++) encoder.copyBufferToBuffer(timing.resolve, 256 * k, timing.read, 8 * n * k, 8 * n);
        timing.state = 'copied';
        timing.slots = region ? TIMING_SLOTS : 1;
      }
    }
  }

  /**
   * Milliseconds per pass ({ shadow, lit }) of the latest frame whose timestamps have come back;
   * {} without 'timestamp-query'. Call after submitting the frame that render() encoded.
   */
  async readTimings(): Promise<Record<string, number>> {
    const timing = this.#timing;
    if (!timing) return {};
    if (timing.state === 'copied') {
      timing.state = 'mapping';
      try {
        await mapWithin(timing.read, TIMING_MAP_DEADLINE_MS);
        const ticks = new BigInt64Array(timing.read.getMappedRange().slice(0));
        timing.read.unmap();
        const out: Record<string, number> = {};
        for (let slot = 0; slot < timing.slots; slot++)
          TIMED_PASSES.forEach((name, i) => {
            const k = TIMED_PASSES.length * slot + i;
            const ns = Number(ticks[2 * k + 1] - ticks[2 * k]);
            // Timestamps may be quantized or reordered; a negative span means "unknown".
            if (ns >= 0) out[slot ? `${name} 2` : name] = ns / 1e6;
          });
        timing.last = out;
      } catch (err) {
        // A map that never settled: stop timing (the stats say so). Else the device was lost or
        // destroyed while mapping: keep the last numbers.
        if (err instanceof MapStalled) this.#timingStalled = true;
      } finally {
        timing.state = 'idle';
      }
    }
    return { ...timing.last };
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
      this.#timing.read.destroy();
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

  #writeScene(view: View, width: number, height: number, wireOpacity: number, patchColours: boolean): void {
    const sphere = boundingSphere(this.#bounds);
    SCENE_UNIFORMS.write(this.#sceneData, {
      viewProj: view.viewProj,
      lightViewProj: this.#lightViewProj,
      model: view.model,
      eye: [...view.eye, sphere.radius],
      toLight: [...DEFAULT_LIGHT_DIR, 1 / this.shadowMapSize],
      // The ground sits at the cage's lowest point, a hair lower so it never z-fights the surface.
      center: [...sphere.center, this.#bounds.min[1] - sphere.radius * 1e-3],
      viewport: [width, height, wireOpacity, patchColours ? 1 : 0],
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
