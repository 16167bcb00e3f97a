// One semi-sharp crease on a bicubic B-spline patch's u = 0 side, in closed form
// (Nießner, Loop, Greiner 2012, "Efficient Evaluation of Semi-Smooth Creases in Catmull-Clark
// Subdivision Surfaces"; the derivation is in the comments below).
//
// Why a closed form: a quad whose crease runs straight through two valence-4 corners
// (OpenSubdiv's single-crease patch) would otherwise need ceil(σ) levels of refinement.
// Across the crease the surface is a 1D scheme (crease vertex fixed for ⌊σ⌋ levels, one
// blended level, smooth afterwards); along it, the ordinary cubic B-spline. So only the
// row in u changes, and it changes into piecewise B-spline weights on the original row.
//
// Row convention: b0, b1, b2, b3 with b1 ON the crease at u = 0 and the row running away
// from it (b0 is the point across the crease, b2/b3 inside the patch). The patch layout is
// row-major: cp[4r + c], row r ~ v, column c ~ u, so the crease is grid column 1.
//
// Everything is written as WEIGHTS on b0..b3 (value and d/du), never as the 4×4 matrix
// M = A⁻¹·diag(1, 2^k, 4^k, 8^k)·A·L^k, whose entries grow like 8^k:
// each weight below is bounded by 2 in magnitude, including the d/du weights (the 1/r of the
// local parameter cancels the r in front of every term that is not b1, and b1's d/du weight
// is taken as minus the sum of the others, which is exact because Σ B'(t) = 0). The same
// code in f32 is wgsl/cc/crease-basis.wgsl; keep the two in step.
import { SHARPNESS_INFINITE } from '../mesh/index.ts';
import { bsplineBasis } from './bspline.ts';

/** Weights on b0..b3 of one row: value = Σ value[i]·b_i, d/du = Σ du[i]·b_i. */
export interface CreaseWeights {
  value: Float64Array;
  du: Float64Array;
}

export function creaseWeights(): CreaseWeights {
  return { value: new Float64Array(4), du: new Float64Array(4) };
}

// Scratch for the basis (the module is single-threaded; no re-entrancy between calls).
const Bt = new Float64Array(4),
  Dt = new Float64Array(4);

/** C(phantom, u) with phantom = (2b1 − b2, b1, b2, b3): the infinitely sharp row (OpenSubdiv's phantom point). */
function phantomWeights(u: number, w: Float64Array, d: Float64Array): void {
  bsplineBasis(u, Bt, Dt);
  w[0] = 0;
  w[1] = 2 * Bt[0] + Bt[1];
  w[2] = Bt[2] - Bt[0];
  w[3] = Bt[3];
  d[0] = 0;
  d[1] = 2 * Dt[0] + Dt[1];
  d[2] = Dt[2] - Dt[0];
  d[3] = Dt[3];
}

/**
 * C(level-k row, u/r) with r = 2^-k: the B-spline of the polygon after k sharp steps,
 * valid on u ∈ [0, r]. The level-k row in terms of b:
 *   c0 = r·b0 + (1−r)·b1,  c1 = b1,  c2 = (1−r)·b1 + r·b2,
 *   c3 = (1 − 2r + r³)·b1 + (2r − 2r³)·b2 + r³·b3.
 * d/du carries the factor 1/r of the local parameter; it is folded into the weights.
 */
function levelWeights(r: number, u: number, w: Float64Array, d: Float64Array): void {
  bsplineBasis(u / r, Bt, Dt); // u/r = u·2^k is exact
  const r2 = r * r,
    r3 = r2 * r,
    q = 1 - r;
  w[0] = r * Bt[0];
  w[1] = q * Bt[0] + Bt[1] + q * Bt[2] + (1 - 2 * r + r3) * Bt[3]; // all terms ≥ 0: no cancellation
  w[2] = r * Bt[2] + (2 * r - 2 * r3) * Bt[3];
  w[3] = r3 * Bt[3];
  d[0] = Dt[0];
  d[2] = Dt[2] + (2 - 2 * r2) * Dt[3];
  d[3] = r2 * Dt[3];
  d[1] = -(d[0] + d[2] + d[3]);
}

const Pw = new Float64Array(4),
  Pd = new Float64Array(4);

/**
 * Weights of one row across a crease of sharpness `sigma` at u ∈ [0,1] (Nießner, Loop, Greiner 2012).
 * OpenSubdiv semantics: sigma is float32 (read through Math.fround); ≤ 0 (or NaN) is smooth,
 * ≥ 10 infinitely sharp; σ = k + f with k = ⌊σ⌋ and f exact.
 *   σ ≥ 10 : phantom(u)
 *   u ≥ r  : phantom(u)                                    (r = 2^-k; for k = 0 only u = 1, where it equals the rest)
 *   f = 0  : u < r : level-k(u)
 *   f > 0  : r/2 ≤ u < r : f·phantom(u) + (1−f)·level-k(u)
 *            u < r/2     : f·level-(k+1)(u) + (1−f)·level-k(u)
 */
export function creaseRowWeights(sigma: number, u: number, out: CreaseWeights = creaseWeights()): CreaseWeights {
  const s = Math.fround(sigma);
  const w = out.value,
    d = out.du;
  if (!(s > 0)) {
    bsplineBasis(u, w, d);
    return out;
  }
  if (s >= SHARPNESS_INFINITE) {
    phantomWeights(u, w, d);
    return out;
  }
  const k = Math.floor(s),
    f = s - k;
  const r = 2 ** -k;
  if (u >= r) {
    phantomWeights(u, w, d);
    return out;
  }
  levelWeights(r, u, w, d);
  if (f === 0) return out;
  if (u >= r / 2) phantomWeights(u, Pw, Pd);
  else levelWeights(r / 2, u, Pw, Pd);
  for (let i = 0; i < 4; i++) {
    w[i] = f * Pw[i] + (1 - f) * w[i];
    d[i] = f * Pd[i] + (1 - f) * d[i];
  }
  return out;
}

export interface CreaseRowPoint {
  P: number[];
  dPdu: number[];
}

/**
 * Evaluate one row of 4 points across the crease. `row` holds the 4 points b0..b3 as
 * consecutive vectors of any dimension (e.g. 12 numbers for xyz).
 */
export function evalCreaseRow(sigma: number, u: number, row: ArrayLike<number>): CreaseRowPoint {
  if (row.length % 4 !== 0) throw new RangeError(`a row is 4 points: got ${row.length} numbers`);
  const dim = row.length / 4;
  const { value, du } = creaseRowWeights(sigma, u);
  const P = new Array<number>(dim).fill(0),
    dPdu = new Array<number>(dim).fill(0);
  for (let i = 0; i < 4; i++) {
    for (let c = 0; c < dim; c++) {
      P[c] += value[i] * row[dim * i + c];
      dPdu[c] += du[i] * row[dim * i + c];
    }
  }
  return { P, dPdu };
}

export interface CreasePatchPoint {
  P: [number, number, number];
  dPdu: [number, number, number];
  dPdv: [number, number, number];
  /** normalize(dPdu × dPdv); NaNs where that cross product vanishes. */
  N: [number, number, number];
}

/**
 * A 4×4 bicubic B-spline patch (cp: 16 xyz points, cp[3(4r + c) + xyz], row r ~ v,
 * column c ~ u, corner c0 at grid (1,1)) with a semi-sharp crease of sharpness
 * `sigma` along its u = 0 side (grid column 1). Tensor form: the crease weights in u, the
 * plain B-spline in v, evaluated separably as P(u,v) = Σ_c w_c(u)·(Σ_r B_r(v)·cp[r][c]).
 * Infinitely sharp (σ ≥ 10) gives the phantom column 0 = 2·col1 − col2 (OpenSubdiv's phantom points).
 */
export function evalCreasePatch(cp: ArrayLike<number>, sigma: number, u: number, v: number): CreasePatchPoint {
  if (cp.length !== 48) throw new RangeError(`a patch is 16 xyz points: got ${cp.length} numbers`);
  const { value: wu, du: wd } = creaseRowWeights(sigma, u);
  const bv = new Float64Array(4),
    dv = new Float64Array(4);
  bsplineBasis(v, bv, dv);
  const P: [number, number, number] = [0, 0, 0];
  const Pu: [number, number, number] = [0, 0, 0];
  const Pv: [number, number, number] = [0, 0, 0];
  for (let c = 0; c < 4; c++) {
    // Column c reduced in v first (value and d/dv), then weighted in u.
    for (let x = 0; x < 3; x++) {
      let col = 0,
        colV = 0;
      for (let r = 0; r < 4; r++) {
        const p = cp[3 * (4 * r + c) + x];
        col += bv[r] * p;
        colV += dv[r] * p;
      }
      P[x] += wu[c] * col;
      Pu[x] += wd[c] * col;
      Pv[x] += wu[c] * colV;
    }
  }
  const n: [number, number, number] = [Pu[1] * Pv[2] - Pu[2] * Pv[1], Pu[2] * Pv[0] - Pu[0] * Pv[2], Pu[0] * Pv[1] - Pu[1] * Pv[0]];
  const l = Math.hypot(n[0], n[1], n[2]);
  const N: [number, number, number] = l > 0 ? [n[0] / l, n[1] / l, n[2] / l] : [NaN, NaN, NaN];
  return { P, dPdu: Pu, dPdv: Pv, N };
}
