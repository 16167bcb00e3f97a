/**
 * Single-crease data of the Catmull-Clark preparation (part 3 of the header of src/gpu/cc/build.ts):
 * which level faces are single-crease patches (one semi-sharp crease along a side, evaluated in
 * closed form with no level refined for it), and which cage vertices on a straight semi-sharp
 * crease take their limit from the same closed form (their 3×3 neighbourhood and σ).
 */
import { type HalfEdges, SHARPNESS_INFINITE } from '../../mesh/index.ts';
import { type Level, isQuadHe } from './levels.ts';

const INF = SHARPNESS_INFINITE;

const semiSharp = (s: number): boolean => s > 0 && s < INF;

/** Is v an interior valence-4 vertex of quads (no holes round it) without vertex sharpness? */
function plainValence4(L: Level, v: number): boolean {
  const m = L.he;
  if (L.boundary[v] || L.vertSharp[v] !== 0) return false;
  if (m.vertHeOffsets[v + 1] - m.vertHeOffsets[v] !== 4 || m.vertEdgeOffsets[v + 1] - m.vertEdgeOffsets[v] !== 4) return false;
  for (let k = m.vertHeOffsets[v]; k < m.vertHeOffsets[v + 1]; k++) {
    const h = m.vertHe[k];
    if (!isQuadHe(m, h) || L.hole[m.heFace[h]]) return false;
  }
  return true;
}

/** Round an interior vertex: the half-edge leaving it after h (twin of the previous). */
const turnHe = (m: HalfEdges, h: number): number => m.heTwin[m.hePrev[h]];

/**
 * A single-crease patch (Nießner, Loop, Greiner 2012; OpenSubdiv's isSingleCreasePatch conditions): level face g
 * is a quad whose 4 corners are interior valence-4 vertices of quads without vertex sharpness,
 * and the only sharp edges at its corners are the 3 collinear edges A'A, AB, BB' of one of its
 * sides AB, all of the same semi-sharp σ. Then its limit is the tensor product of the cubic
 * B-spline along the crease and the closed-form 1D crease basis across it: only the rules of the
 * 4 corners and of the edges at them reach the sub-patches, and they stay of this kind as σ
 * decays. Returns the corner to start the patch's frame at (B: the crease AB becomes the frame's
 * x = 0 side, grid column 1) and σ; null if g is not such a face.
 *
 * Not under Chaikin's rule: there an edge's child is averaged with the semi-sharp edges at its
 * ends, so the crease's sharpness inside the patch's support depends on edges beyond it (the
 * crease's continuation past A' and B') and no longer decays as σ − 1 a level. Such faces refine.
 */
export function singleCrease(L: Level, g: number): { start: number; sigma: number } | null {
  if (L.chaikin) return null;
  const m = L.he;
  const a0 = m.faceOffsets[g];
  if (m.faceOffsets[g + 1] - a0 !== 4) return null;
  let side = -1;
  for (let j = 0; j < 4; j++) {
    if (!plainValence4(L, m.faceIndices[a0 + j])) return null;
    if (L.edgeSharp[m.heEdge[a0 + j]] !== 0) {
      if (side >= 0) return null;
      side = j;
    }
  }
  if (side < 0) return null;
  const h = a0 + side;
  const sigma = L.edgeSharp[m.heEdge[h]];
  if (!semiSharp(sigma)) return null;
  // The crease goes straight on through A and B: the edges opposite AB round A and round B.
  const ea = m.heEdge[turnHe(m, turnHe(m, h))];
  const eb = m.heEdge[turnHe(m, turnHe(m, m.heTwin[h]))];
  if (L.edgeSharp[ea] !== sigma || L.edgeSharp[eb] !== sigma) return null;
  const crease = [m.heEdge[h], ea, eb];
  for (let j = 0; j < 4; j++) {
    const v = m.faceIndices[a0 + j];
    for (let k = m.vertEdgeOffsets[v]; k < m.vertEdgeOffsets[v + 1]; k++) {
      const e = m.vertEdges[k];
      if (L.edgeSharp[e] !== 0 && !crease.includes(e)) return null;
    }
  }
  return { start: (side + 1) & 3, sigma };
}

/**
 * A vertex on a straight semi-sharp crease (two opposite edges of the same semi-sharp σ, the
 * other two smooth, an interior valence-4 vertex of quads, no vertex sharpness): its limit is
 * the corner of the single-crease patches round it, in closed form (wgsl/cc/build.wgsl
 * vertexLimit). Its 3×3 neighbourhood at 3a + b (global indices), a across the crease, b along it,
 * oriented as the faces (a toward the first ring neighbour, b toward the next: cross(∂a, ∂b) is
 * the surface normal); null if v is not such a vertex (and under Chaikin's rule, as singleCrease).
 */
export function creaseVertexGrid(L: Level, v: number): { idx: number[]; sigma: number } | null {
  if (L.chaikin) return null;
  const m = L.he;
  if (!plainValence4(L, v)) return null;
  let h = m.vertHe[m.vertHeOffsets[v]];
  if (L.edgeSharp[m.heEdge[h]] !== 0) h = turnHe(m, h);
  const hs = [h, turnHe(m, h), turnHe(m, turnHe(m, h)), turnHe(m, turnHe(m, turnHe(m, h)))];
  const s = hs.map((x) => L.edgeSharp[m.heEdge[x]]);
  if (s[0] !== 0 || s[2] !== 0 || !semiSharp(s[1]) || s[3] !== s[1]) return null;
  const pos: [number, number][] = [
    [2, 1],
    [1, 2],
    [0, 1],
    [1, 0],
  ];
  const grid = new Array<number>(9).fill(-1);
  grid[4] = v;
  for (let k = 0; k < 4; k++) {
    const [a, b] = pos[k],
      [a2, b2] = pos[(k + 1) & 3];
    grid[3 * a + b] = m.faceIndices[m.heNext[hs[k]]];
    // Face k holds ring neighbours k and k + 1 (the next half-edge round v leaves to prev's start).
    grid[3 * (a + a2 - 1) + (b + b2 - 1)] = m.faceIndices[m.heNext[m.heNext[hs[k]]]];
  }
  return { idx: grid.map((x) => L.base + x), sigma: s[1] };
}
