// Plain-data types for subdivision cages. DOM-free and dependency-free: the GPU
// code and the CPU reference both consume these flat arrays directly.

/** Boundary interpolation, as OpenSubdiv's `Sdc::Options::VtxBoundaryInterpolation`. */
export type BoundaryInterpolation = 'edge-and-corner' | 'edge-only' | 'none';
/** Crease subdivision method, as OpenSubdiv's `Sdc::Options::CreasingMethod`. */
export type CreasingMethod = 'uniform' | 'chaikin';

export interface SubdivOptions {
  boundary: BoundaryInterpolation;
  creasing: CreasingMethod;
}

/** OpenSubdiv's defaults: edge-and-corner boundaries, uniform creasing (Catmark triangles). */
export const DEFAULT_OPTIONS: Readonly<SubdivOptions> = Object.freeze({
  boundary: 'edge-and-corner',
  creasing: 'uniform',
});

/** Sharpness at or above this value is infinitely sharp (OpenSubdiv's SHARPNESS_INFINITE). */
export const SHARPNESS_INFINITE = 10;

export interface CreaseTag {
  v0: number;
  v1: number;
  /** float32-rounded, clamped to [0, 10]; 10 means infinitely sharp. */
  sharpness: number;
  /** 1-based source line (0 when built in code). */
  line: number;
}

export interface CornerTag {
  v: number;
  sharpness: number;
  line: number;
}

/** A `t` line we keep but do not interpret (e.g. face-varying options), for round trips. */
export interface RawTag {
  text: string;
  line: number;
}

/**
 * A polygonal cage as read from OBJ: faces of any size, counter-clockwise seen
 * from outside, 0-based indices.
 */
export interface Cage {
  /** xyz per vertex. */
  positions: Float64Array;
  /** Face f has corners faceIndices[faceOffsets[f] .. faceOffsets[f+1]). Length nFaces+1. */
  faceOffsets: Int32Array;
  faceIndices: Int32Array;
  /** Optional `vt` data: uv pairs, and per face corner a uv index or -1. */
  uvs: Float64Array;
  faceUvIndices: Int32Array;
  /** Optional `vn` data: xyz triples, and per face corner a normal index or -1. */
  normals: Float64Array;
  faceNormalIndices: Int32Array;
  creases: CreaseTag[];
  corners: CornerTag[];
  /** Vertices that the 'edge-and-corner' boundary rule leaves unsharpened although they have one
   * face (src/mesh/manifold.ts: the copies of a non-manifold crease vertex, which OpenSubdiv does
   * not sharpen). Absent in a cage read from a file. */
  cornerExempt?: readonly number[];
  /** Face ids tagged `t hole`. */
  holes: number[];
  holeLines: number[];
  /** Subdivision options given by `t interpolateboundary` / `t creasemethod`, if any. */
  fileOptions: Partial<SubdivOptions>;
  /** Other `t` lines, kept verbatim. */
  rawTags: RawTag[];
  /** 1-based source line of each face (0 when built in code). */
  faceLines: Int32Array;
  /** 1-based source line of each vertex (0 when built in code). */
  vertexLines: Int32Array;
}

export function vertexCount(c: Cage): number {
  return c.positions.length / 3;
}

export function faceCount(c: Cage): number {
  return c.faceOffsets.length - 1;
}

/** Build a cage from plain arrays (for generators and tests). */
export function makeCage(
  positions: ArrayLike<number>,
  faces: ArrayLike<number>[],
  tags: { creases?: [number, number, number][]; corners?: [number, number][]; holes?: number[] } = {},
): Cage {
  const offs = new Int32Array(faces.length + 1);
  let n = 0;
  for (let f = 0; f < faces.length; f++) {
    n += faces[f].length;
    offs[f + 1] = n;
  }
  const idx = new Int32Array(n);
  let k = 0;
  for (const f of faces) for (let j = 0; j < f.length; j++) idx[k++] = f[j];
  const minus = new Int32Array(n).fill(-1);
  return {
    positions: Float64Array.from(positions),
    faceOffsets: offs,
    faceIndices: idx,
    uvs: new Float64Array(0),
    faceUvIndices: minus,
    normals: new Float64Array(0),
    faceNormalIndices: minus.slice(),
    creases: (tags.creases ?? []).map(([v0, v1, s]) => ({ v0, v1, sharpness: normaliseSharpness(s), line: 0 })),
    corners: (tags.corners ?? []).map(([v, s]) => ({ v, sharpness: normaliseSharpness(s), line: 0 })),
    holes: [...(tags.holes ?? [])],
    holeLines: (tags.holes ?? []).map(() => 0),
    fileOptions: {},
    rawTags: [],
    faceLines: new Int32Array(faces.length),
    vertexLines: new Int32Array(positions.length / 3),
  };
}

/** float32-round a sharpness, clamp to [0, 10] (>= 10 is infinite and stored as 10). */
export function normaliseSharpness(s: number): number {
  if (!(s > 0)) return 0;
  if (s >= SHARPNESS_INFINITE) return SHARPNESS_INFINITE;
  return Math.fround(s);
}
