/**
 * CPU preparation of a cage for the compute tessellator, done once per model: plain flat
 * arrays that the GPU passes read (cage → topology → patches in the data flow).
 *
 *  - Faces are split into triangles (quads along the 0–2 diagonal, n-gons as a fan from corner
 *    0); faces without a limit surface are dropped: tagged holes, and under boundary
 *    interpolation 'none' the faces at an unsharpened boundary (OpenSubdiv's rule, as
 *    computeSharpness), so no surface evaluates a face the subdivision says is not there.
 *    Each triangle keeps its source face.
 *  - Vertex normals: area-weighted (the sum of the faces' cross products), for Phong
 *    tessellation and for the adaptive factor rule.
 *  - Edges: every undirected edge of the triangulation once, canonically from its lower to
 *    its higher vertex index. The factor of an edge is computed and stored once per edge, so the
 *    two triangles of an edge can never disagree; its line runs in that canonical direction.
 *  - Per triangle: its three edge ids, and its pattern frame (clamped.ts chooseFrame) from the
 *    reverse flags, packed in one u32.
 */
import type { Cage, SubdivOptions } from '../mesh/types.ts';
import { DEFAULT_OPTIONS, buildTopology, computeSharpness } from '../mesh/index.ts';
import { chooseFrame, type Reverse } from '../pattern/clamped.ts';
import { NO_OWNER, OWNER_WORD, PATTERN_FRAME_WORD } from './contract.ts';

export interface PreparedMesh {
  vertexCount: number;
  triangleCount: number;
  edgeCount: number;
  /** xyz per cage vertex (f32). */
  positions: Float32Array;
  /** Unit vertex normals, xyz per cage vertex (f32). */
  normals: Float32Array;
  /** Three cage vertices per triangle. */
  triVerts: Uint32Array;
  /** Three edge ids per triangle: edge i joins corner i to corner i+1. */
  triEdges: Uint32Array;
  /** Pattern frame per triangle (packPatternFrame). */
  triPatternFrame: Uint32Array;
  /** Source face of each triangle. */
  triFace: Uint32Array;
  /** Two cage vertices per edge, lower index first. */
  edgeVerts: Uint32Array;
  /** One triangle of each edge and the edge's local index in it (an OwnerWord, contract.ts). */
  edgeOwner: Uint32Array;
  /** One triangle of each vertex and its corner in it (an OwnerWord), NO_OWNER if unused. */
  vertexOwner: Uint32Array;
  /** Bounding box diagonal length: the model's size for tolerances. */
  size: number;
  bboxMin: [number, number, number];
  bboxMax: [number, number, number];
}

export { NO_OWNER };

/** The pattern frame of a triangle with these reverse flags, as a PatternFrameWord (its bits are
 * declared in contract.ts). */
export function packPatternFrame(reverse: Reverse): number {
  return PATTERN_FRAME_WORD.pack(chooseFrame(reverse));
}

/** Faces without a limit surface under these options (tagged holes; boundary 'none' adds more). */
function holeFaces(cage: Cage, options: Partial<SubdivOptions>): Set<number> {
  const holes = new Set(cage.holes);
  if (options.boundary === 'none') {
    const topo = buildTopology(cage);
    const { hole } = computeSharpness(cage, topo, { ...DEFAULT_OPTIONS, ...options });
    for (let f = 0; f < hole.length; f++) if (hole[f]) holes.add(f);
  }
  return holes;
}

export function prepareMesh(cage: Cage, options: Partial<SubdivOptions> = cage.fileOptions): PreparedMesh {
  const nV = cage.positions.length / 3;
  const holes = holeFaces(cage, options);
  const tris: number[] = [];
  const faces: number[] = [];
  const nFaces = cage.faceOffsets.length - 1;
  for (let f = 0; f < nFaces; f++) {
    if (holes.has(f)) continue;
    const s = cage.faceOffsets[f];
    const n = cage.faceOffsets[f + 1] - s;
    for (let k = 1; k + 1 < n; k++) {
      tris.push(cage.faceIndices[s], cage.faceIndices[s + k], cage.faceIndices[s + k + 1]);
      faces.push(f);
    }
  }
  const nT = tris.length / 3;

  const P = cage.positions;
  const acc = new Float64Array(3 * nV);
  for (let f = 0; f < nFaces; f++) {
    // Newell's method: robust for non-planar polygons, area-weighted.
    const s = cage.faceOffsets[f];
    const n = cage.faceOffsets[f + 1] - s;
    let nx = 0,
      ny = 0,
      nz = 0;
    for (let k = 0; k < n; k++) {
      const a = cage.faceIndices[s + k],
        b = cage.faceIndices[s + ((k + 1) % n)];
      nx += (P[3 * a + 1] - P[3 * b + 1]) * (P[3 * a + 2] + P[3 * b + 2]);
      ny += (P[3 * a + 2] - P[3 * b + 2]) * (P[3 * a] + P[3 * b]);
      nz += (P[3 * a] - P[3 * b]) * (P[3 * a + 1] + P[3 * b + 1]);
    }
    for (let k = 0; k < n; k++) {
      const v = cage.faceIndices[s + k];
      acc[3 * v] += nx;
      acc[3 * v + 1] += ny;
      acc[3 * v + 2] += nz;
    }
  }
  const normals = new Float32Array(3 * nV);
  for (let v = 0; v < nV; v++) {
    const l = Math.hypot(acc[3 * v], acc[3 * v + 1], acc[3 * v + 2]);
    if (l > 0) for (let c = 0; c < 3; c++) normals[3 * v + c] = acc[3 * v + c] / l;
    else normals[3 * v + 2] = 1; // an unused or degenerate vertex: any unit vector
  }

  const edgeIds = new Map<number, number>();
  const edgeVerts: number[] = [];
  const edgeOwner: number[] = [];
  const triEdges = new Uint32Array(3 * nT);
  const triPatternFrame = new Uint32Array(nT);
  const vertexOwner = new Uint32Array(nV).fill(NO_OWNER);
  for (let t = 0; t < nT; t++) {
    const reverse: boolean[] = [];
    for (let i = 0; i < 3; i++) {
      const a = tris[3 * t + i],
        b = tris[3 * t + ((i + 1) % 3)];
      const lo = Math.min(a, b),
        hi = Math.max(a, b);
      const key = lo * nV + hi;
      let e = edgeIds.get(key);
      if (e === undefined) {
        e = edgeVerts.length / 2;
        edgeIds.set(key, e);
        edgeVerts.push(lo, hi);
        edgeOwner.push(OWNER_WORD.pack({ corner: i, tri: t }));
      }
      triEdges[3 * t + i] = e;
      reverse.push(a > b); // walked from its higher vertex: reversed
      if (vertexOwner[a] === NO_OWNER) vertexOwner[a] = OWNER_WORD.pack({ corner: i, tri: t });
    }
    triPatternFrame[t] = packPatternFrame(reverse as unknown as Reverse);
  }

  const bboxMin: [number, number, number] = [Infinity, Infinity, Infinity];
  const bboxMax: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  for (let v = 0; v < nV; v++) {
    if (vertexOwner[v] === NO_OWNER) continue;
    for (let c = 0; c < 3; c++) {
      bboxMin[c] = Math.min(bboxMin[c], P[3 * v + c]);
      bboxMax[c] = Math.max(bboxMax[c], P[3 * v + c]);
    }
  }
  const size = nT ? Math.hypot(bboxMax[0] - bboxMin[0], bboxMax[1] - bboxMin[1], bboxMax[2] - bboxMin[2]) : 0;

  return {
    vertexCount: nV,
    triangleCount: nT,
    edgeCount: edgeVerts.length / 2,
    positions: Float32Array.from(P),
    normals,
    triVerts: Uint32Array.from(tris),
    triEdges,
    triPatternFrame,
    triFace: Uint32Array.from(faces),
    edgeVerts: Uint32Array.from(edgeVerts),
    edgeOwner: Uint32Array.from(edgeOwner),
    vertexOwner,
    size,
    bboxMin,
    bboxMax,
  };
}
