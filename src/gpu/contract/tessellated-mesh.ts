/**
 * The contract between the compute tessellator (tessellator.ts) and everything that draws or
 * reads its output (the renderer, the headless CLI, the checks). DOM-free.
 *
 * The output is one big flat mesh, stored once and drawn by every pass:
 *   positions  array<f32>, 3 per vertex            usage VERTEX | STORAGE | COPY_SRC
 *   normals    array<f32>, 3 per vertex            usage VERTEX | STORAGE | COPY_SRC
 *   bary       array<u32>, 1 per vertex            (w1, w2) of the source triangle, 16 bits each
 *              (tess.ts BARY_WORD);
 *              a vertex at a corner of its source triangle stores 0 (corner 0), 0xFFFFFFFF
 *              (corner 1) or 0xFFFFFFFE (corner 2): those sums exceed 2^16, so they cannot be
 *              a real point (w1 + w2 ≤ 2^16, and no non-corner weight reaches 2^16).
 *   srcTri     array<u32>, 1 per vertex            the source (cage) triangle
 *   indices    array<u32>, 3 per triangle          usage INDEX | STORAGE | COPY_SRC
 *   drawArgs   5 × u32 drawIndexedIndirect args    usage INDIRECT | STORAGE | COPY_SRC
 *              (indexCount, instanceCount = 1, firstIndex = 0, baseVertex = 0, firstInstance = 0),
 *              written by the GPU every time the mesh is rebuilt.
 *   counts     4 × u32: vertexCount, triangleCount, budget scale (f32 bits), the budget candidate taken (0: scale 1)
 */
export interface TessellatedMesh {
  positions: GPUBuffer;
  normals: GPUBuffer;
  bary: GPUBuffer;
  srcTri: GPUBuffer;
  indices: GPUBuffer;
  drawArgs: GPUBuffer;
  counts: GPUBuffer;
  vertexCapacity: number;
  triangleCapacity: number;
}

/** How the edge tess factors are chosen each rebuild. */
export interface FactorParams {
  mode: 'fixed' | 'adaptive';
  /** The one factor of fixed mode (clamped to [1, maxFactor]). */
  fixedFactor: number;
  /** Global LOD scale of adaptive mode: factors grow with it (1 = the default density). */
  lodScale: number;
  /** Column-major view-projection matrix (WebGPU clip space, z in 0..1). */
  viewProj: Float32Array;
  /** Eye position in world space. */
  eye: [number, number, number];
  /** Viewport height in pixels (the adaptive rule aims at a screen-space error in pixels). */
  viewportHeight: number;
  /** Vertical field of view in radians. */
  fovY: number;
}

/** The bary word's corner sentinels (declared with BARY_WORD in tess.ts). */
export { BARY_CORNER1, BARY_CORNER2 } from './tess.ts';
