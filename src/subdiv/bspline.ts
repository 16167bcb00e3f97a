// Uniform bicubic B-spline patches: basis, 16-point gathering with boundary /
// infinite-crease phantoms, closed-form evaluation.
import { type HalfEdges, isRegularVertex, vertexRing } from '../mesh/index.ts';
import { isInf } from '../mesh/index.ts';
import type { Level } from './level.ts';

/** Cubic B-spline basis and derivative at t. */
export function bsplineBasis(t: number, b: Float64Array | number[], d: Float64Array | number[]): void {
  const s = 1 - t,
    t2 = t * t,
    t3 = t2 * t;
  b[0] = (s * s * s) / 6;
  b[1] = (3 * t3 - 6 * t2 + 4) / 6;
  b[2] = (-3 * t3 + 3 * t2 + 3 * t + 1) / 6;
  b[3] = t3 / 6;
  d[0] = -0.5 * s * s;
  d[1] = 0.5 * (3 * t2 - 4 * t);
  d[2] = 0.5 * (-3 * t2 + 2 * t + 1);
  d[3] = 0.5 * t2;
}

/**
 * Evaluate a patch: cp holds 16 xyz points row-major (row ~ v, column ~ u),
 * corner c0 at grid (1,1). Writes P, dP/du, dP/dv into out[0..9).
 */
export function evalBSplinePatch(cp: Float64Array, u: number, v: number, out: Float64Array | number[]): void {
  const bu = [0, 0, 0, 0],
    du = [0, 0, 0, 0],
    bv = [0, 0, 0, 0],
    dv = [0, 0, 0, 0];
  bsplineBasis(u, bu, du);
  bsplineBasis(v, bv, dv);
  for (let c = 0; c < 9; c++) out[c] = 0;
  for (let r = 0; r < 4; r++) {
    // Reduce row r in u first (separable).
    let px = 0,
      py = 0,
      pz = 0,
      qx = 0,
      qy = 0,
      qz = 0;
    for (let c = 0; c < 4; c++) {
      const o = 3 * (4 * r + c);
      px += bu[c] * cp[o];
      py += bu[c] * cp[o + 1];
      pz += bu[c] * cp[o + 2];
      qx += du[c] * cp[o];
      qy += du[c] * cp[o + 1];
      qz += du[c] * cp[o + 2];
    }
    out[0] += bv[r] * px;
    out[1] += bv[r] * py;
    out[2] += bv[r] * pz;
    out[3] += bv[r] * qx;
    out[4] += bv[r] * qy;
    out[5] += bv[r] * qz;
    out[6] += dv[r] * px;
    out[7] += dv[r] * py;
    out[8] += dv[r] * pz;
  }
}

export function isBoundaryVertex(m: HalfEdges, v: number): boolean {
  for (let k = m.vertEdgeOffsets[v]; k < m.vertEdgeOffsets[v + 1]; k++) if (m.edgeFaceCount[m.vertEdges[k]] === 1) return true;
  return false;
}

/** Is face f of level L a regular B-spline patch (all four corners regular)? */
export function isRegularFace(L: Level, f: number): boolean {
  const m = L.he;
  const a = m.faceOffsets[f];
  if (m.faceOffsets[f + 1] - a !== 4) return false;
  for (let j = 0; j < 4; j++) {
    const v = m.faceIndices[a + j];
    if (!isRegularVertex(m, v, L.edgeSharp, L.vertSharp, isBoundaryVertex(m, v))) return false;
  }
  return true;
}

// Each corner's axes (an affine map onto the 4 × 4 grid): grid position g and local axes a
// (towards c_{j+1}), b (towards c_{j-1}).
const G = [
  [1, 1],
  [2, 1],
  [2, 2],
  [1, 2],
];
const A = [
  [1, 0],
  [0, 1],
  [-1, 0],
  [0, -1],
];
const B = [
  [0, 1],
  [-1, 0],
  [0, -1],
  [1, 0],
];

/**
 * Gather the 16 control points of regular quad f (caller checked isRegularFace),
 * with phantom rows/columns beyond infinitely sharp face edges. Returns null if
 * some point is missing (should not happen for a regular face).
 */
export function gatherPatch(L: Level, f: number): Float64Array | null {
  const m = L.he;
  const P = L.pos;
  const cp = new Float64Array(48).fill(NaN);
  const put = (col: number, row: number, v: number): void => {
    if (v < 0 || col < 0 || col > 3 || row < 0 || row > 3) return;
    const o = 3 * (4 * row + col);
    cp[o] = P[3 * v];
    cp[o + 1] = P[3 * v + 1];
    cp[o + 2] = P[3 * v + 2];
  };
  const a0 = m.faceOffsets[f];
  const dest = (h: number): number => m.faceIndices[m.heNext[h]];
  const opp = (h: number): number => m.faceIndices[m.heNext[m.heNext[h]]];
  for (let j = 0; j < 4; j++) {
    const h = a0 + j;
    const v = m.faceIndices[h];
    const ring = vertexRing(m, v, h);
    if (!ring) return null;
    const R = ring.he,
      n = R.length;
    const r = R.indexOf(h);
    if (r < 0) return null;
    const face = (i: number): number => {
      if (!ring.boundary) return R[(((r + i) % n) + n) % n];
      const k = r + i;
      return k >= 0 && k < n ? R[k] : -1;
    };
    const f1 = face(1),
      f3 = ring.boundary ? face(-1) : face(3),
      f2 = ring.boundary ? -1 : face(2);
    const g = G[j],
      ax = A[j],
      bx = B[j];
    put(g[0], g[1], v);
    if (f1 >= 0) {
      put(g[0] - ax[0] + bx[0], g[1] - ax[1] + bx[1], opp(f1)); // d1
      put(g[0] - ax[0], g[1] - ax[1], m.faceIndices[m.hePrev[f1]]); // e2
    }
    if (f3 >= 0) {
      put(g[0] - bx[0], g[1] - bx[1], dest(f3)); // e3
      put(g[0] + ax[0] - bx[0], g[1] + ax[1] - bx[1], opp(f3)); // d3
    }
    if (f2 >= 0) put(g[0] - ax[0] - bx[0], g[1] - ax[1] - bx[1], opp(f2)); // d2
  }
  const sharpSide = (j: number): boolean => isInf(L.edgeSharp[m.heEdge[a0 + j]]);
  const refl = (dst: number, p1: number, p2: number): void => {
    for (let c = 0; c < 3; c++) cp[3 * dst + c] = 2 * cp[3 * p1 + c] - cp[3 * p2 + c];
  };
  if (sharpSide(0)) for (let c = 0; c < 4; c++) refl(c, 4 + c, 8 + c);
  if (sharpSide(2)) for (let c = 0; c < 4; c++) refl(12 + c, 8 + c, 4 + c);
  if (sharpSide(3)) for (let r = 0; r < 4; r++) refl(4 * r, 4 * r + 1, 4 * r + 2);
  if (sharpSide(1)) for (let r = 0; r < 4; r++) refl(4 * r + 3, 4 * r + 2, 4 * r + 1);
  for (let i = 0; i < 48; i++) if (!Number.isFinite(cp[i])) return null;
  return cp;
}
