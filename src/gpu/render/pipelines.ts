/**
 * The renderer's pipelines: the WGSL each compiles (RENDER_SHADERS), the bind group layouts of
 * contract/render.ts created on a device, and every pipeline Renderer (renderer.ts) draws with
 * (createRenderPipelines), with the mesh's vertex buffers and the lit draw's face states, which
 * the instanced tessellator's drawer shares (meshFaceStates).
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
import { heatRenderWgsl } from '../acc/heat.ts';
import { CAGE_LINE_STRIDE } from './cage-mesh.ts';
import {
  HEAT_RENDER_GROUP,
  PATCH_KIND_GROUP,
  RENDER_BIND_GROUPS,
  RENDER_PIPELINE_GROUPS,
  SCENE_GROUP,
  SHADING_GROUP,
  WIRE_ARGS_GROUP,
  WIRE_LINES_GROUP,
  type RenderBindGroup,
  type RenderPipelineName,
} from '../contract/render.ts';
import { scenePrelude, sceneWgsl } from '../contract/contract.ts';

/** The lit shader's sources with its three groups where `at` puts them (SCENE_GROUP.moved and so
 * on: the instanced tessellator's drawer includes it beside groups of its own). */
export function litShader(
  at: { scene: typeof SCENE_GROUP; shading: typeof SHADING_GROUP; patchKind: typeof PATCH_KIND_GROUP } = {
    scene: SCENE_GROUP,
    shading: SHADING_GROUP,
    patchKind: PATCH_KIND_GROUP,
  },
): readonly string[] {
  return [scenePrelude(at.scene), commonWGSL, at.shading.wgsl(), shadingWGSL, at.patchKind.wgsl(), litWGSL];
}

/** The WGSL sources of each pipeline's shader module, in order (the two cage pipelines share one). */
export const RENDER_SHADERS: Record<RenderPipelineName, readonly string[]> = {
  shadow: [sceneWgsl, commonWGSL, shadowWGSL],
  lit: litShader(),
  ground: [sceneWgsl, commonWGSL, SHADING_GROUP.wgsl(), shadingWGSL, groundWGSL],
  backdrop: [sceneWgsl, commonWGSL, backdropWGSL],
  wireframe: [sceneWgsl, commonWGSL, WIRE_LINES_GROUP.wgsl(), wireLinesWGSL],
  cage: [sceneWgsl, commonWGSL, wireCageWGSL],
  wireArgs: [WIRE_ARGS_GROUP.wgsl(), wireArgsWGSL],
};

/** The heat pipelines' shader module's sources (src/gpu/acc/heat.ts). */
export const HEAT_SHADER: readonly string[] = [sceneWgsl, commonWGSL, heatRenderWgsl, HEAT_RENDER_GROUP.wgsl(), heatWGSL];

export const DEPTH_FORMAT: GPUTextureFormat = 'depth32float';
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

/** The renderer's bind group layouts (vertexStorage absent where the vertex stage reads no
 * storage) and its pipelines. Those a first frame draws with (shadow, lit, ground, backdrop) are
 * made at once; the others (the error views' heat, the wireframe, the cage overlay) the first time
 * they are asked for: on a software GPU each one compiled before the first frame delayed it. */
export interface RenderPipelines {
  layouts: Record<RenderBindGroup, GPUBindGroupLayout>;
  /** [open, closed] (Renderer.setMesh's `closed`). */
  shadow: GPURenderPipeline[];
  /** [front faces, back faces]: a closed surface draws the first, an open one both (see the lit
   * pipelines below). */
  lit: GPURenderPipeline[];
  /** The heat map (src/gpu/acc/heat.ts) for the front or the back faces, as the lit ones; null
   * without vertex-stage storage, as is its bind group layout. */
  heat: (back: boolean) => GPURenderPipeline | null;
  heatGroupLayout: GPUBindGroupLayout | null;
  ground: GPURenderPipeline;
  backdrop: GPURenderPipeline;
  wire: () => GPURenderPipeline | null;
  wireArgs: () => GPUComputePipeline;
  cageHidden: () => GPURenderPipeline;
  cageVisible: () => GPURenderPipeline;
}

/** `make`, called the first time the result is asked for and kept. */
function once<T>(make: () => T): () => T {
  let made: { value: T } | null = null;
  return () => (made ??= { value: make() }).value;
}

/** Creates the bind group layouts and every pipeline of a Renderer drawing into `colorFormat`
 * with `sampleCount` samples; `vertexStorage`: whether the vertex stage may read storage buffers
 * (Renderer.vertexStorage). */
export function createRenderPipelines(
  device: GPUDevice,
  colorFormat: GPUTextureFormat,
  sampleCount: number,
  vertexStorage: boolean,
): RenderPipelines {
  const shadow: GPURenderPipeline[] = [];
  const lit: GPURenderPipeline[] = [];
  const layouts = {} as Record<RenderBindGroup, GPUBindGroupLayout>;
  for (const [name, entries] of Object.entries(RENDER_BIND_GROUPS) as [RenderBindGroup, readonly GPUBindGroupLayoutEntry[]][]) {
    // A vertex-visible storage layout is itself invalid where the vertex stage has none.
    if (name === 'vertexStorage' && !vertexStorage) continue;
    layouts[name] = device.createBindGroupLayout({ label: `${name} bind group layout`, entries: [...entries] });
  }

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
  const wireModule = once(() => module('wireframe'));
  const cageModule = once(() => module('cage'));

  const heatGroupLayout = vertexStorage
    ? device.createBindGroupLayout({ label: 'heat bind group layout', entries: HEAT_RENDER_GROUP.layoutEntries() })
    : null;
  // The lit pipeline's groups with the heat group in place of the patch colours' (group 2).
  const heatLayout = heatGroupLayout
    ? device.createPipelineLayout({
        label: 'heat pipeline layout',
        bindGroupLayouts: [layouts.scene, layouts.shading, heatGroupLayout],
      })
    : null;
  const heatModule = once(() => device.createShaderModule({ label: 'heat shader', code: HEAT_SHADER.join('\n') }));

  const multisample = { count: sampleCount };
  const blend: GPUBlendState = {
    color: { srcFactor: 'src-alpha', dstFactor: 'one-minus-src-alpha', operation: 'add' },
    alpha: { srcFactor: 'one', dstFactor: 'one-minus-src-alpha', operation: 'add' },
  };
  const opaqueTarget = [{ format: colorFormat }];
  const blendedTarget = [{ format: colorFormat, blend }];
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
    shadow[+closed] = device.createRenderPipeline({
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
    lit[+back] = device.createRenderPipeline({
      label: `lit pipeline (${side})`,
      layout: pipelineLayout('lit'),
      vertex: { module: litModule, entryPoint: vertexStorage ? 'litVertex' : 'litVertexPlain', buffers: MESH_BUFFERS },
      fragment: { module: litModule, entryPoint: 'litFragment', targets: opaqueTarget },
      primitive,
      depthStencil,
      multisample,
    });
  }
  const heatPipeline = (back: boolean) => {
    if (!heatLayout) return null;
    const side = back ? 'back faces, depth-biased behind the front faces' : 'front faces';
    const { primitive, depthStencil } = meshFaceStates(back, DEPTH_FORMAT);
    return device.createRenderPipeline({
      label: `heat pipeline (${side})`,
      layout: heatLayout,
      vertex: { module: heatModule(), entryPoint: 'heatVertex', buffers: MESH_BUFFERS },
      fragment: { module: heatModule(), entryPoint: 'heatFragment', targets: opaqueTarget },
      primitive,
      depthStencil,
      multisample,
    });
  };
  const heatFront = once(() => heatPipeline(false));
  const heatBack = once(() => heatPipeline(true));
  const ground = device.createRenderPipeline({
    label: 'ground pipeline',
    layout: pipelineLayout('ground'),
    vertex: { module: groundModule, entryPoint: 'groundVertex' },
    fragment: { module: groundModule, entryPoint: 'groundFragment', targets: blendedTarget },
    primitive: { topology: 'triangle-strip', cullMode: 'none' },
    depthStencil: overlayDepth('less'),
    multisample,
  });
  const backdrop = device.createRenderPipeline({
    label: 'backdrop pipeline',
    layout: pipelineLayout('backdrop'),
    vertex: { module: backdropModule, entryPoint: 'backdropVertex' },
    fragment: { module: backdropModule, entryPoint: 'backdropFragment', targets: opaqueTarget },
    primitive: { topology: 'triangle-list' },
    depthStencil: overlayDepth('always'),
    multisample,
  });
  const wire = once(() =>
    vertexStorage
      ? device.createRenderPipeline({
          label: 'wireframe pipeline',
          layout: pipelineLayout('wireframe'),
          vertex: { module: wireModule(), entryPoint: 'wireVertex' },
          fragment: { module: wireModule(), entryPoint: 'wireFragment', targets: blendedTarget },
          primitive: { topology: 'line-list' },
          depthStencil: overlayDepth('less-equal'),
          multisample,
        })
      : null,
  );
  const cageLayout = once(() => pipelineLayout('cage'));
  const cagePipeline = (label: string, opacity: number, compare: GPUCompareFunction) =>
    device.createRenderPipeline({
      label,
      layout: cageLayout(),
      vertex: {
        module: cageModule(),
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
      fragment: { module: cageModule(), entryPoint: 'cageFragment', targets: blendedTarget, constants: { OPACITY: opacity } },
      primitive: { topology: 'line-list' },
      depthStencil: overlayDepth(compare),
      multisample,
    });
  // The cage mostly floats outside the limit surface; where it dips behind, show it as a ghost.
  const cageHidden = once(() => cagePipeline('cage overlay (hidden part) pipeline', 0.22, 'greater'));
  const cageVisible = once(() => cagePipeline('cage overlay pipeline', 1.0, 'less-equal'));
  const wireArgs = once(() =>
    device.createComputePipeline({
      label: 'wireframe args pipeline',
      layout: pipelineLayout('wireArgs'),
      compute: { module: module('wireArgs'), entryPoint: 'wireArgsMain' },
    }),
  );
  const heat = (back: boolean) => (back ? heatBack() : heatFront());

  return { layouts, shadow, lit, heat, heatGroupLayout, ground, backdrop, wire, wireArgs, cageHidden, cageVisible };
}
