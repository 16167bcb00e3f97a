/**
 * The renderer's side of the contract (src/gpu/render/renderer.ts, wgsl/render/*.wgsl): its
 * per-frame uniforms (SCENE_UNIFORMS), its bind group layouts and which pipeline uses which, as the
 * descriptors the renderer creates (RENDER_BIND_GROUPS, RENDER_PIPELINE_GROUPS), the ground's
 * extent and the patch colours. What its shaders start with is assembled in contract.ts (sceneWgsl).
 */
import { STAGE, defineBindGroup } from './define.ts';
import { defineStruct } from './layout.ts';

/**
 * The renderer's per-frame uniforms (wgsl/render/common.wgsl reads them as `scene`), written by
 * Renderer every frame. The fields' comments travel into the generated WGSL.
 */
export const SCENE_UNIFORMS = defineStruct('SceneUniforms', [
  ['viewProj', 'mat4x4<f32>', 'World to clip space of the camera (WebGPU clip space, z in 0..1).'],
  ['lightViewProj', 'mat4x4<f32>', 'World to clip space of the light (the shadow map).'],
  ['model', 'mat4x4<f32>', "Model to world: a rotation only (the model's up axis to +Y), so it also turns normals."],
  ['eye', 'vec4<f32>', "xyz: the camera's position; w: the model's bounding radius."],
  ['toLight', 'vec4<f32>', 'xyz: unit vector towards the light; w: one shadow-map texel in uv units.'],
  ['center', 'vec4<f32>', "xyz: the bounding sphere's centre; w: the ground's height."],
  ['viewport', 'vec4<f32>', 'x, y: render target size in pixels; z: wireframe opacity; w: 1 for patch colours, else 0.'],
  ['look', 'vec4<f32>', 'x: the material (MATERIALS index: 0 clay, 1 metal); yzw: unused.'],
] as const);

/** The surface's materials under the studio rig (wgsl/render/lit.wgsl shade), by scene.look.x. */
export const MATERIALS = ['clay', 'metal'] as const;
export type Material = (typeof MATERIALS)[number];

/** The per-frame uniforms (SCENE_UNIFORMS), group 0 of every render pipeline but wireArgs. */
export const SCENE_GROUP = defineBindGroup(
  0,
  { scene: { binding: 0, space: 'uniform', type: 'SceneUniforms' } },
  STAGE.VERTEX | STAGE.FRAGMENT,
);

/** The shadow map and its comparison sampler (wgsl/render/shading.wgsl), group 1 of the lit,
 * heat and ground pipelines. */
export const SHADING_GROUP = defineBindGroup(
  1,
  {
    shadowMap: { binding: 0, type: 'texture_depth_2d', texture: { sampleType: 'depth' } },
    shadowSampler: { binding: 1, type: 'sampler_comparison', sampler: { type: 'comparison' } },
  },
  STAGE.FRAGMENT,
);

/** The patch colours (wgsl/render/lit.wgsl), group 2 of the lit pipelines: each vertex's source
 * triangle (the tessellator's srcTri output, read by vertex index: an indexed draw's vertex_index
 * is the index value) and that triangle's patch kind + 1 (0: none; Renderer.setPatchKinds). */
export const PATCH_KIND_GROUP = defineBindGroup(
  2,
  {
    srcTri: { binding: 0, space: 'read', type: 'array<u32>' },
    patchKind: { binding: 1, space: 'read', type: 'array<u32>' },
  },
  STAGE.VERTEX,
);

/** The wireframe's index and position buffers (wgsl/render/wire-lines.wgsl), group 1 of the
 * wireframe pipeline: the same layout as PATCH_KIND_GROUP (vertexStorage), other names. */
export const WIRE_LINES_GROUP = defineBindGroup(
  1,
  {
    indices: { binding: 0, space: 'read', type: 'array<u32>' },
    positions: { binding: 1, space: 'read', type: 'array<f32>' },
  },
  STAGE.VERTEX,
);

/** The wireframe's indirect args pass (wgsl/render/wire-args.wgsl): the mesh's drawIndexedIndirect
 * args in, the wireframe's drawIndirect args out. */
export const WIRE_ARGS_GROUP = defineBindGroup(0, {
  drawArgs: { binding: 0, space: 'read', type: 'array<u32, 5>' },
  wireArgs: { binding: 1, space: 'read_write', type: 'array<u32, 4>' },
});

/** The heat map (wgsl/render/heat.wgsl), group 2 of the heat pipelines in place of the patch
 * colours': the values, 2 f32 per vertex, by vertex index, and HeatUniforms (src/gpu/acc/heat.ts). */
export const HEAT_RENDER_GROUP = defineBindGroup(
  2,
  {
    heatValues: { binding: 0, space: 'read', type: 'array<f32>', visibility: STAGE.VERTEX },
    heat: { binding: 1, space: 'uniform', type: 'HeatUniforms' },
  },
  STAGE.VERTEX | STAGE.FRAGMENT,
);

/** The sRGB blit's picture (wgsl/render/blit-srgb.wgsl, src/gpu/render/srgb-blit.ts), read with
 * textureLoad: unfilterable-float, as the 'auto' layout it replaced inferred. */
export const BLIT_GROUP = defineBindGroup(
  0,
  { source: { binding: 0, type: 'texture_2d<f32>', texture: { sampleType: 'unfilterable-float' } } },
  STAGE.FRAGMENT,
);

/** The renderer's bind group layouts, entry for entry, from the declarations above. The WGSL
 * declares each at its group index in the pipelines of RENDER_PIPELINE_GROUPS
 * (tests/gpu/contract/contract.test.ts compares them). */
export const RENDER_BIND_GROUPS = {
  /** The per-frame uniforms (SCENE_UNIFORMS). */
  scene: SCENE_GROUP.layoutEntries(),
  /** The shadow map and its comparison sampler. */
  shading: SHADING_GROUP.layoutEntries(),
  /** Two arrays read by vertex index: the wireframe's indices and positions (WIRE_LINES_GROUP),
   * or the patch colours' source triangles and kinds (PATCH_KIND_GROUP): one layout. */
  vertexStorage: PATCH_KIND_GROUP.layoutEntries(),
  /** The mesh's drawIndexedIndirect args in, the wireframe's drawIndirect args out. */
  wireArgs: WIRE_ARGS_GROUP.layoutEntries(),
} as const satisfies Record<string, readonly GPUBindGroupLayoutEntry[]>;

export type RenderBindGroup = keyof typeof RENDER_BIND_GROUPS;

/** Which bind group layout sits at each group index of each of the renderer's pipelines. */
export const RENDER_PIPELINE_GROUPS = {
  shadow: ['scene'],
  lit: ['scene', 'shading', 'vertexStorage'],
  ground: ['scene', 'shading'],
  backdrop: ['scene'],
  wireframe: ['scene', 'vertexStorage'],
  cage: ['scene'],
  wireArgs: ['wireArgs'],
} as const satisfies Record<string, readonly RenderBindGroup[]>;

export type RenderPipelineName = keyof typeof RENDER_PIPELINE_GROUPS;

/** How far the ground plane reaches from the model's centre, in bounding radii: the ground shader
 * draws it that far, camera.ts fits the clip planes and the light's box around it. */
export const GROUND_EXTENT = 4;

/** Patch kinds (src/gpu/cc/build.ts PatchKind) in patch-colour mode, sRGB, indexed by kind: the
 * lit shader's palette (PATCH_SRGB) and the demo's legend. */
export const PATCH_COLOURS: readonly { kind: number; name: string; srgb: readonly [number, number, number] }[] = [
  { kind: 0, name: 'regular', srgb: [0.56, 0.8, 0.52] },
  // As NVIDIA's sample's "show irregular patches": irregular quads blue, triangles purple.
  { kind: 1, name: 'irregular quad', srgb: [0.36, 0.56, 0.98] },
  { kind: 2, name: 'triangle / n-gon region', srgb: [0.72, 0.46, 0.92] },
  { kind: 3, name: 'crease', srgb: [0.96, 0.82, 0.3] },
];
