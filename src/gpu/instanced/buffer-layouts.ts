/**
 * The instanced tessellator's buffer layouts shared with its WGSL (wgsl/instanced/common.wgsl,
 * levels.wgsl, draw.wgsl): the cage buffer's arena (INST_CAGE), the uniform structs (INST_PARAMS,
 * INST_BUCKET, INST_FRAME), the packed
 * edge-owner word, the bucket count and stride, the patch record's size, the draw records' bytes
 * and the work buffer's layout.
 */
import { defineStruct } from '../contract/layout.ts';
import { defineArena, defineBits } from '../contract/define.ts';
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
  ['offTriVerts', 'u32'],
  ['offPatches', 'u32'],
  ['offEdgeOwner', 'u32'],
  ['offPatternIJ', 'u32'],
  ['offPatternIdx', 'u32'],
  ['offEntries', 'u32'],
  ...INST_CAGE.offsetFields,
  // work word offsets (wgsl/instanced/levels.wgsl).
  ['offWanted', 'u32'],
  ['offEdgeCode', 'u32'],
  ['offPatchLevel', 'u32'],
  ['offCounts', 'u32'],
  ['offLists', 'u32'],
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

/** Word offsets of the work buffer's parts (wgsl/instanced/levels.wgsl), set per mesh by setMesh. */
export interface WorkLayout {
  wanted: number;
  edgeCode: number;
  patchLevel: number;
  counts: number;
  lists: number;
  words: number;
}
