/**
 * Power-of-two refinement patterns for instanced tessellation (NVIDIA's 2009 sample, after
 * Boubekeur & Schlick's generic refinement pattern) and the T-junction snap of Dyken et al.,
 * in a canonical-direction form (each edge walked from its lower global vertex id). Pure TypeScript: the
 * GPU path (src/gpu/instanced/instanced.ts, wgsl/instanced/*.wgsl) reads the packed patterns built here
 * and its WGSL snap is the line-for-line twin of snapEdgeParam / snapVertex.
 *
 * Domains and orientation (integer pattern coordinates (i, j), parameter (u, v) = (i, j) / L):
 *   quad      corners c0 = (0,0), c1 = (L,0), c2 = (L,L), c3 = (0,L), counter-clockwise;
 *             vertices (i, j) for 0 ≤ i, j ≤ L, vertex index j·(L+1) + i (row-major, i along u);
 *             (L+1)² vertices, 2L² triangles.
 *   triangle  corners c0 = (0,0), c1 = (L,0), c2 = (0,L); vertices (i, j) with i + j ≤ L, row j
 *             holds L+1−j vertices, vertex index triRowStart(L, j) + i; (L+1)(L+2)/2 vertices,
 *             L² triangles.
 * Every triangle is counter-clockwise in (u, v), as the cage faces are seen from outside.
 *
 * Quad diagonals are "union jack": in each quadrant of the square they point at the centre. The
 * cells touching a corner then have their diagonal through that corner, so no triangle of the
 * pattern has vertices on two different edges except at a corner, and the snap can never flip
 * one (a diagonal the other way in the (L−1, 0) cell flips as soon as both its edges snap away).
 * The diagonals in the (0,0) and (1,1) quadrants also lie along u = v, the 0–2 split of a quad
 * into cage triangles (src/gpu/tess/prepare.ts), so no triangle straddles the two surface triangles.
 *
 * Patch edges: edge k runs from corner k to corner k+1 (quad: v=0, u=1, v=1, u=0; triangle:
 * v=0, u+v=1, u=0). The edge parameter t ∈ [0, L] is measured from corner k. An edge is
 * "canonical" on a patch when its corner k has the lower global vertex id; the snap rounds the
 * parameter down in the canonical direction, so the two patches of an edge, which walk it in
 * opposite directions, compute the same points whatever their own pattern levels.
 */

/** The pattern levels: 1, 2, 4, … 64 (index = log2 of the level). */
export const POW2_LEVELS = [1, 2, 4, 8, 16, 32, 64] as const;
export const MAX_POW2_LEVEL = 64;
export const POW2_LEVEL_COUNT = POW2_LEVELS.length;

export type PatchDomain = 'quad' | 'tri';

export interface Pow2Pattern {
  domain: PatchDomain;
  level: number;
  /** Integer pattern coordinates (i, j) per vertex. */
  ij: Uint32Array;
  /** (u, v) = (i, j) / level per vertex (exact in f32: level is a power of two). */
  uv: Float32Array;
  /** Three vertex indices per triangle, counter-clockwise in (u, v). */
  indices: Uint32Array;
}

export function isPow2Level(L: number): boolean {
  return Number.isInteger(L) && L >= 1 && L <= MAX_POW2_LEVEL && (L & (L - 1)) === 0;
}

function checkLevel(L: number): void {
  if (!isPow2Level(L)) throw new Error(`pattern level ${L} is not a power of two in [1, ${MAX_POW2_LEVEL}]`);
}

export function quadVertexCount(L: number): number {
  return (L + 1) * (L + 1);
}
export function quadTriangleCount(L: number): number {
  return 2 * L * L;
}
export function triVertexCount(L: number): number {
  return ((L + 1) * (L + 2)) / 2;
}
export function triTriangleCount(L: number): number {
  return L * L;
}
export function patternVertexCount(domain: PatchDomain, L: number): number {
  return domain === 'quad' ? quadVertexCount(L) : triVertexCount(L);
}
export function patternTriangleCount(domain: PatchDomain, L: number): number {
  return domain === 'quad' ? quadTriangleCount(L) : triTriangleCount(L);
}

export function quadVertexIndex(L: number, i: number, j: number): number {
  return j * (L + 1) + i;
}
/** First vertex of row j of the triangle pattern: rows 0..j−1 hold L+1, L, … L+2−j vertices. */
export function triRowStart(L: number, j: number): number {
  return j * (L + 1) - (j * (j - 1)) / 2;
}
export function triVertexIndex(L: number, i: number, j: number): number {
  return triRowStart(L, j) + i;
}

export function quadPattern(L: number): Pow2Pattern {
  checkLevel(L);
  const n = L + 1;
  const ij = new Uint32Array(2 * n * n);
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) ij.set([i, j], 2 * quadVertexIndex(L, i, j));
  const indices = new Uint32Array(3 * quadTriangleCount(L));
  let k = 0;
  const h = L / 2;
  for (let j = 0; j < L; j++) {
    for (let i = 0; i < L; i++) {
      const a = quadVertexIndex(L, i, j),
        b = quadVertexIndex(L, i + 1, j);
      const c = quadVertexIndex(L, i + 1, j + 1),
        d = quadVertexIndex(L, i, j + 1);
      // Union jack: the diagonal a–c in the (0,0) and (1,1) quadrants, b–d in the other two
      // (at L = 1 the single cell takes a–c, along u = v).
      const main = L === 1 || i < h === j < h;
      if (main) indices.set([a, b, c, a, c, d], k);
      else indices.set([a, b, d, b, c, d], k);
      k += 6;
    }
  }
  return { domain: 'quad', level: L, ij, uv: Float32Array.from(ij, (x) => x / L), indices };
}

export function triPattern(L: number): Pow2Pattern {
  checkLevel(L);
  const ij = new Uint32Array(2 * triVertexCount(L));
  for (let j = 0; j <= L; j++) for (let i = 0; i + j <= L; i++) ij.set([i, j], 2 * triVertexIndex(L, i, j));
  const tris: [number, number][][] = [];
  for (let j = 0; j < L; j++) {
    for (let i = 0; i + j < L; i++) {
      tris.push([
        [i, j],
        [i + 1, j],
        [i, j + 1],
      ]);
      if (i + j + 1 < L)
        tris.push([
          [i + 1, j],
          [i + 1, j + 1],
          [i, j + 1],
        ]);
    }
  }
  // At L ≥ 4 the grid has, at each corner, an inverted triangle with vertices on both edges of
  // that corner but not the corner itself; snapping both away flips it. Flip the diagonal of
  // the parallelogram it forms with the corner triangle, so both triangles hold the corner.
  // (At L = 2 the one inverted triangle has a vertex on each of the three edges: a monotone
  // snap keeps their cyclic order, so it cannot flip.)
  if (L >= 4) {
    const at = (ps: [number, number][]) => tris.findIndex((t) => t.every(([x, y], q) => x === ps[q][0] && y === ps[q][1]));
    const flip = (corner: [number, number][], inverted: [number, number][], a: [number, number][], b: [number, number][]) => {
      tris[at(corner)] = a;
      tris[at(inverted)] = b;
    };
    flip(
      [
        [0, 0],
        [1, 0],
        [0, 1],
      ],
      [
        [1, 0],
        [1, 1],
        [0, 1],
      ],
      [
        [0, 0],
        [1, 0],
        [1, 1],
      ],
      [
        [0, 0],
        [1, 1],
        [0, 1],
      ],
    );
    flip(
      [
        [L - 1, 0],
        [L, 0],
        [L - 1, 1],
      ],
      [
        [L - 1, 0],
        [L - 1, 1],
        [L - 2, 1],
      ],
      [
        [L - 1, 0],
        [L, 0],
        [L - 2, 1],
      ],
      [
        [L, 0],
        [L - 1, 1],
        [L - 2, 1],
      ],
    );
    flip(
      [
        [0, L - 1],
        [1, L - 1],
        [0, L],
      ],
      [
        [1, L - 2],
        [1, L - 1],
        [0, L - 1],
      ],
      [
        [1, L - 2],
        [1, L - 1],
        [0, L],
      ],
      [
        [1, L - 2],
        [0, L],
        [0, L - 1],
      ],
    );
  }
  const indices = Uint32Array.from(tris.flatMap((t) => t.map(([x, y]) => triVertexIndex(L, x, y))));
  return { domain: 'tri', level: L, ij, uv: Float32Array.from(ij, (x) => x / L), indices };
}

export function pow2Pattern(domain: PatchDomain, L: number): Pow2Pattern {
  return domain === 'quad' ? quadPattern(L) : triPattern(L);
}

// ---- the snap ------------------------------------------------------------------------------

/**
 * Snap edge parameter t ∈ [0, P] (measured from the patch's corner k) of a pattern at level P
 * onto the coarse grid of an edge at level Le ≤ P, rounding down in the canonical direction
 * (the T-junction snap of Dyken, Reimers, Seland 2009, made canonical so both patches of an
 * edge agree). Monotone and onto {0, R, 2R, … P} with R = P / Le; 0 and P are fixed.
 */
export function snapEdgeParam(t: number, P: number, Le: number, canonical: boolean): number {
  const R = P / Le;
  if (canonical) return Math.floor(t / R) * R;
  return P - Math.floor((P - t) / R) * R;
}

/** The edges (0..3 quad, 0..2 triangle) vertex (i, j) of a level-P pattern lies on, and its
 * parameter t along each (from corner k). */
export function vertexEdges(domain: PatchDomain, P: number, i: number, j: number): { edge: number; t: number }[] {
  const out: { edge: number; t: number }[] = [];
  if (domain === 'quad') {
    if (j === 0) out.push({ edge: 0, t: i });
    if (i === P) out.push({ edge: 1, t: j });
    if (j === P) out.push({ edge: 2, t: P - i });
    if (i === 0) out.push({ edge: 3, t: P - j });
  } else {
    if (j === 0) out.push({ edge: 0, t: i });
    if (i + j === P) out.push({ edge: 1, t: j });
    if (i === 0) out.push({ edge: 2, t: P - j });
  }
  return out;
}

/** (i, j) of the point at parameter t on edge k of a level-P pattern. */
export function edgePoint(domain: PatchDomain, P: number, edge: number, t: number): [number, number] {
  if (domain === 'quad')
    return (
      [
        [t, 0],
        [P, t],
        [P - t, P],
        [0, P - t],
      ] as [number, number][]
    )[edge];
  return (
    [
      [t, 0],
      [P - t, t],
      [0, P - t],
    ] as [number, number][]
  )[edge];
}

/**
 * Snapped pattern coordinates of vertex (i, j) at patch level P, given each patch edge's level
 * (levels[k] ≤ P, powers of two) and whether the patch walks edge k canonically. Only boundary
 * vertices move (interior ones stay on the level-P grid, as Dyken et al.'s semi-uniform scheme):
 * a vertex on one edge slides along it; corners are fixed points of every snap.
 */
export function snapVertex(
  domain: PatchDomain,
  P: number,
  i: number,
  j: number,
  levels: ArrayLike<number>,
  canonical: ArrayLike<boolean>,
): [number, number] {
  const on = vertexEdges(domain, P, i, j);
  if (on.length !== 1) return [i, j]; // interior, or a corner
  const { edge, t } = on[0];
  return edgePoint(domain, P, edge, snapEdgeParam(t, P, levels[edge], canonical[edge]));
}

// ---- packing for the GPU --------------------------------------------------------------------

/** Where one pattern lies in the packed buffers (units: vertices and indices). */
export interface PatternEntry {
  domain: PatchDomain;
  level: number;
  baseVertex: number;
  firstIndex: number;
  vertexCount: number;
  indexCount: number;
}

/**
 * Every pattern of both domains in one vertex array and one index array (the refinement
 * patterns of Boubekeur & Schlick 2005, as NVIDIA's 2009 "Instanced Tessellation" sample), in the
 * order quad 1, 2, … 64, then triangle 1, 2, … 64 (entry index = domain·7 + log2 L).
 *   ij       one u32 per vertex: i | j << 16 (the vertex shader reads it as vertex_index, which
 *            includes the draw's baseVertex)
 *   indices  u32, local to their pattern (a draw adds baseVertex)
 */
export interface PackedPatterns {
  entries: PatternEntry[];
  ij: Uint32Array;
  indices: Uint32Array;
}

export function packPatterns(): PackedPatterns {
  const entries: PatternEntry[] = [];
  const ij: number[] = [];
  const idx: number[] = [];
  for (const domain of ['quad', 'tri'] as const) {
    for (const L of POW2_LEVELS) {
      const p = pow2Pattern(domain, L);
      entries.push({
        domain,
        level: L,
        baseVertex: ij.length,
        firstIndex: idx.length,
        vertexCount: p.ij.length / 2,
        indexCount: p.indices.length,
      });
      for (let v = 0; v < p.ij.length / 2; v++) ij.push(p.ij[2 * v] | (p.ij[2 * v + 1] << 16));
      for (const x of p.indices) idx.push(x);
    }
  }
  return { entries, ij: Uint32Array.from(ij), indices: Uint32Array.from(idx) };
}
