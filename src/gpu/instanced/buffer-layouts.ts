/**
 * The instanced tessellator's buffer layouts shared with its WGSL (wgsl/instanced/common.wgsl,
 * levels.wgsl, draw.wgsl): the cage buffer's arena (INST_CAGE), the uniform structs (INST_PARAMS,
 * INST_BUCKET, INST_FRAME), the static and work buffers' arenas (INST_STATIC, INST_WORK), the
 * packed edge-owner word, the bucket count and stride, the patch record's size and the draw
 * records' bytes.
 */
import { defineStruct } from '../contract/layout.ts';
import { defineArena, defineBindGroup, defineBits, STAGE } from '../contract/define.ts';
import { POW2_LEVEL_COUNT } from '../../pattern/pow2.ts';

/**
 * cageBuf (f32, wgsl/instanced/common.wgsl cagePos, cageNormal, phongAlpha): the cage positions and
 * unit vertex normals (3 per vertex), then the Phong surface's α per triangle edge (3 per
 * triangle). Positions first: an ACC surface's build (src/gpu/acc/patches.ts encode) reads xyz per
 * cage vertex from offset 0 of this buffer.
 */
export const INST_CAGE = defineArena<'positions' | 'normals' | 'phongAlpha', { vertices: number; triangles: number }>([
  ['positions', (s) => 3 * s.vertices],
  ['normals', (s) => 3 * s.vertices],
  ['phongAlpha', (s) => 3 * s.triangles],
]);

/**
 * staticBuf (u32, uploaded once per mesh; wgsl/instanced/common.wgsl): the prepared triangles'
 * vertices (3 per triangle), the patch records (PATCH_WORDS each), each mesh edge's owner
 * (INST_OWNER_WORD), then the power-of-two patterns of every level and domain: their (i, j) points
 * and index lists as src/pattern/pow2.ts lays them out, and each bucket's pattern entry (base
 * vertex, first index, index count, vertex count).
 */
export const INST_STATIC = defineArena<
  'triVerts' | 'patches' | 'edgeOwner' | 'patternIJ' | 'patternIdx' | 'entries',
  { triangles: number; patches: number; edges: number; patternIJWords: number; patternIndices: number }
>([
  ['triVerts', (s) => 3 * s.triangles],
  ['patches', (s) => PATCH_WORDS * s.patches],
  ['edgeOwner', (s) => s.edges],
  ['patternIJ', (s) => s.patternIJWords],
  ['patternIdx', (s) => s.patternIndices],
  ['entries', () => 4 * BUCKETS],
]);

/**
 * work (u32, written by the level passes every frame; wgsl/instanced/levels.wgsl): each patch's
 * wanted level (per-patch mode), each edge's level code, each patch's level, the patch count of
 * each bucket, then each bucket's list of patches (quads: POW2_LEVEL_COUNT lists of up to every
 * quad, then the triangles' the same way).
 */
export const INST_WORK = defineArena<'wanted' | 'edgeCode' | 'patchLevel' | 'counts' | 'lists', { patches: number; edges: number }>([
  ['wanted', (s) => s.patches],
  ['edgeCode', (s) => s.edges],
  ['patchLevel', (s) => s.patches],
  ['counts', () => BUCKETS],
  ['lists', (s) => POW2_LEVEL_COUNT * s.patches],
]);

export const INST_PARAMS = defineStruct('InstParams', [
  ['viewProj', 'mat4x4<f32>'],
  // x, y: viewport size in pixels (dynamic mode).
  ['viewport', 'vec4<f32>'],
  // xyz: the eye in model space (factor-rule mode).
  ['eye', 'vec4<f32>'],
  ['nPatches', 'u32'],
  ['nQuads', 'u32'],
  ['nTris', 'u32'],
  ['nEdges', 'u32'],
  ['mode', 'u32'],
  ['staticLevel', 'u32'],
  ['lodScale', 'f32'],
  ['targetPixels', 'f32'],
  ['pixelError', 'f32'],
  // Factor-rule mode: radians per pixel (fovY / viewport height), as the compute tessellator's Params.
  ['pixelAngle', 'f32'],
  // staticBuf word offsets (wgsl/instanced/common.wgsl), then cageBuf's float offsets (INST_CAGE).
  ...INST_STATIC.offsetFields,
  ...INST_CAGE.offsetFields,
  // work word offsets (INST_WORK, wgsl/instanced/levels.wgsl).
  ...INST_WORK.offsetFields,
  // 1: the renderer-pass lit draw shades facets (wgsl/render/instanced.wgsl; setFlatShading).
  ['flatShading', 'u32'],
] as const);

export const INST_BUCKET = defineStruct('InstBucket', [
  ['listBase', 'u32'],
  ['level', 'u32'],
  ['domain', 'u32'],
  ['baseVertex', 'u32'],
  ['firstIndex', 'u32'],
  ['vertexCount', 'u32'],
  ['triangleCount', 'u32'],
  ['outVertexBase', 'u32'],
  ['outTriangleBase', 'u32'],
  ['instances', 'u32'],
  ['outVertexTotal', 'u32'],
] as const);

/** An edge's owner: the patch and which of its sides (edge k) it is (wgsl/instanced/levels.wgsl). */
export const INST_OWNER_WORD = defineBits('InstOwnerWord', { side: [0, 2], patchId: [2, 30] });

export const INST_FRAME = defineStruct('InstFrame', [
  ['viewProj', 'mat4x4<f32>'],
  ['lightViewProj', 'mat4x4<f32>'],
  ['toLight', 'vec4<f32>'],
  ['eye', 'vec4<f32>'],
] as const);

// ---- bind groups ----------------------------------------------------------------------------
// Every binding of the instanced tessellator's modules, declared here once: the WGSL declarations
// are generated from these (levels.ts and instanced.ts put them in front of the .wgsl files, which
// hold none), and so are the layouts. Group 0 the mesh, 1 the bucket, 2 the pass's own (frame
// uniform or headless output), 3 the surface's.

const VC = STAGE.VERTEX | STAGE.COMPUTE;
const MESH_BUFFERS = {
  params: { binding: 0, space: 'uniform', type: 'InstParams' },
  staticBuf: { binding: 1, space: 'read', type: 'array<u32>', doc: 'INST_STATIC: topology, patches, edge owners, patterns' },
  cageBuf: { binding: 2, space: 'read', type: 'array<f32>', doc: 'INST_CAGE: positions, normals, Phong α' },
} as const;

/** Group 0 of the draws and the headless pass: the mesh, with the work buffer read-only. */
export const INST_DRAW_MESH_GROUP = defineBindGroup(
  0,
  { ...MESH_BUFFERS, work: { binding: 3, space: 'read', type: 'array<u32>', doc: 'INST_WORK (the level passes wrote it)' } },
  VC,
);

/** Group 0 of the level passes: the same buffers, the work buffer as atomics, and the draw records. */
export const INST_LEVELS_GROUP = defineBindGroup(0, {
  ...MESH_BUFFERS,
  work: { binding: 3, space: 'read_write', type: 'array<atomic<u32>>', doc: 'INST_WORK' },
  drawArgs: { binding: 4, space: 'read_write', type: 'array<u32>', doc: 'the indirect draw records (DRAW_ARGS_BYTES)' },
});

/** Group 1: the bucket being drawn, one INST_BUCKET slot per bucket, picked by a dynamic offset. */
export const INST_BUCKET_GROUP = defineBindGroup(
  1,
  { bucket: { binding: 0, space: 'uniform', type: 'InstBucket', hasDynamicOffset: true, minBindingSize: INST_BUCKET.size } },
  VC,
);

/** Group 2 of the instanced tessellator's own lit and shadow draws (wgsl/instanced/frame.wgsl). */
export const INST_FRAME_GROUP = defineBindGroup(
  2,
  { frame: { binding: 0, space: 'uniform', type: 'InstFrame' } },
  STAGE.VERTEX | STAGE.FRAGMENT,
);

/** Group 2 of the headless pass (wgsl/instanced/headless.wgsl): ONE output buffer, so that an ACC
 * surface's two and a displacement lender's three fit the per-stage storage limit. */
export const INST_HEADLESS_GROUP = defineBindGroup(2, {
  outWords: { binding: 1, space: 'read_write', type: 'array<u32>', doc: 'vertices (8 words), their patches, then triangles' },
});

/**
 * Group 3: the surface's buffers, every one at its own binding, so that a configuration binds the
 * names it reads and nothing is renumbered. The exact surface borrows a compute tessellator's four
 * (ccParams … ccWork: src/gpu/instanced/surface-cc.ts); a displacement lender lends three of the
 * same (wgsl/tess/displace.wgsl reads them under those names: src/gpu/instanced/displace-vertex.ts),
 * the Catmull-Clark source being its own lender; an ACC surface reads its patches and points.
 */
export const INST_SURFACE_GROUP = defineBindGroup(
  3,
  {
    ccParams: { binding: 0, space: 'uniform', type: 'Params', doc: "the lending compute tessellator's Params" },
    ccStatic: { binding: 1, space: 'read', type: 'array<u32>', doc: 'its TESS_STATIC arena' },
    ccCage: { binding: 2, space: 'read', type: 'array<f32>', doc: 'its TESS_CAGE arena' },
    ccWork: { binding: 3, space: 'read', type: 'array<u32>', doc: 'its TESS_WORK arena (the exact surface only)' },
    accPatches: { binding: 4, space: 'read', type: 'array<u32>', doc: "AccPatches' patch words" },
    accPoints: { binding: 5, space: 'read', type: 'array<vec4<f32>>', doc: "AccPatches' control points" },
  },
  VC,
);
export type InstSurfaceBinding = keyof typeof INST_SURFACE_GROUP.binding;

/** Buckets: domain (0 quad, 1 triangle) · 7 + log2 level. */
export const BUCKETS = 2 * POW2_LEVEL_COUNT;
/** Bytes between two buckets' uniforms (minUniformBufferOffsetAlignment is at most 256). */
export const BUCKET_STRIDE = 256;
/** Threads of the records pass (wgsl/instanced/levels.wgsl `records`, one per bucket): the power
 * of two at or above BUCKETS (16 for 14); the threads past BUCKETS return at once. */
export const RECORD_THREADS = 2 ** Math.ceil(Math.log2(BUCKETS));
export const PATCH_WORDS = 8;

/** Bytes of drawArgs: 14 indexed records (5 words), then 14 wireframe records (4 words). */
export const DRAW_ARGS_BYTES = 20 * BUCKETS + 16 * BUCKETS;
export const WIRE_ARGS_OFFSET = 20 * BUCKETS;
