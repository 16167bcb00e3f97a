// The single semi-sharp crease in closed form (src/subdiv/crease-basis.ts; Nießner, Loop, Greiner 2012)
// against refinement: (1) the exact CPU reference (src/subdiv, local feature-adaptive
// refinement with OpenSubdiv's crease rules) on jittered tori with a straight crease loop
// of constant sharpness through valence-4 vertices; (2) an independent 1D refinement of one
// row; plus closed values (reference values measured for this project) and the affine-in-f property.
import { describe, expect, it } from 'vitest';
import { makeCage } from '../../src/mesh/index.ts';
import { Surface, type SurfacePoint } from '../../src/subdiv/index.ts';
import { creaseRowWeights, evalCreasePatch, evalCreaseRow } from '../../src/subdiv/crease-basis.ts';

type V = ArrayLike<number>;
const maxDiff = (a: V, b: V): number => {
  let m = 0;
  for (let i = 0; i < b.length; i++) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
};

/** Deterministic jitter (mulberry32). */
function rng(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

// Jittered all-quad torus: NI around the major circle (face u), NJ around the minor (face v).
const NI = 8,
  NJ = 6;
const idx = (i: number, j: number): number => (((i % NI) + NI) % NI) * NJ + (((j % NJ) + NJ) % NJ);
const torusPos = ((): Float64Array => {
  const rand = rng(9),
    p = new Float64Array(3 * NI * NJ);
  for (let i = 0; i < NI; i++) {
    for (let j = 0; j < NJ; j++) {
      const th = (2 * Math.PI * i) / NI,
        ph = (2 * Math.PI * j) / NJ,
        rr = 3 + Math.cos(ph);
      const o = 3 * idx(i, j);
      p[o] = rr * Math.cos(th) + 0.3 * (rand() - 0.5);
      p[o + 1] = rr * Math.sin(th) + 0.3 * (rand() - 0.5);
      p[o + 2] = Math.sin(ph) + 0.3 * (rand() - 0.5);
    }
  }
  return p;
})();
const torusFaces: number[][] = [];
for (let i = 0; i < NI; i++) for (let j = 0; j < NJ; j++) torusFaces.push([idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)]);
const faceId = (i: number, j: number): number => (((i % NI) + NI) % NI) * NJ + (((j % NJ) + NJ) % NJ);
const diag = ((): number => {
  const lo = [Infinity, Infinity, Infinity],
    hi = [-Infinity, -Infinity, -Infinity];
  for (let v = 0; v < NI * NJ; v++)
    for (let c = 0; c < 3; c++) {
      lo[c] = Math.min(lo[c], torusPos[3 * v + c]);
      hi[c] = Math.max(hi[c], torusPos[3 * v + c]);
    }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
})();

/** 16 xyz points, cp[3(4r + c)], with grid column c and row r given as cage vertices by `at(c, r)`. */
function patchFrom(at: (c: number, r: number) => number): Float64Array {
  const cp = new Float64Array(48);
  for (let r = 0; r < 4; r++) for (let c = 0; c < 4; c++) cp.set(torusPos.subarray(3 * at(c, r), 3 * at(c, r) + 3), 3 * (4 * r + c));
  return cp;
}

/**
 * Derivative mismatch. At the patch corners on the crease (u = 0, v ∈ {0,1}) the crease vertex
 * is irregular for the reference while semi-sharp, which then returns the vertex limit with
 * limit tangents whose lengths are not parametric derivatives (SurfacePoint.atVertex): there
 * only P and N are compared.
 */
const derivDiff = (want: SurfacePoint, du: V, dv: V): number =>
  want.atVertex ? 0 : Math.max(maxDiff(du, want.dPdu), maxDiff(dv, want.dPdv));

const SIGMAS = [0.5, 1, 1.5, 2.7, 10, 0, 2.3, 3.7];
// Down to 1e-6 from the crease, the level breakpoints 2^-k (and their neighbours), and beyond.
const US = [0, 1e-6, 3e-5, 2 ** -10, 0.003, 2 ** -6, 0.0624, 0.1, 0.125, 0.126, 0.2, 0.25, 0.37, 0.5, 0.5000001, 0.71, 1];
const VS = [0, 0.21, 0.5, 0.83, 1];
const TOL = 1e-12 * diag;

describe('single semi-sharp crease: closed form vs exact refinement (jittered torus, valence 4)', () => {
  // Crease loop A runs around the minor circle through i = I0: faces (I0, j) have it on their
  // u = 0 side (their own patch layout is the closed form's), faces (I0-1, j) on u = 1 (mirror
  // the columns, evaluate at 1 - u; d/du changes sign).
  const I0 = 2,
    J0 = 3;
  for (const sigma of SIGMAS) {
    it(`sharpness ${sigma}: loop across u (faces with the crease at u = 0 and at u = 1)`, () => {
      const creases: [number, number, number][] = [];
      for (let j = 0; j < NJ; j++) creases.push([idx(I0, j), idx(I0, j + 1), sigma]);
      const S = new Surface(makeCage(torusPos, torusFaces, { creases }));
      let worst = 0;
      for (const j of [0, 4]) {
        const cpL = patchFrom((c, r) => idx(I0 - 1 + c, j - 1 + r)); // crease at u = 0
        const cpR = patchFrom((c, r) => idx(I0 - 1 - c + 2, j - 1 + r)); // face (I0-1, j) mirrored: column c = 3 - c'
        for (const u of US)
          for (const v of VS) {
            const want = S.evaluate(faceId(I0, j), u, v);
            const got = evalCreasePatch(cpL, sigma, u, v);
            worst = Math.max(worst, maxDiff(got.P, want.P), derivDiff(want, got.dPdu, got.dPdv));
            expect(maxDiff(got.N, want.N), `N at (${u}, ${v})`).toBeLessThanOrEqual(1e-10);

            const wantR = S.evaluate(faceId(I0 - 1, j), 1 - u, v);
            const gotR = evalCreasePatch(cpR, sigma, u, v);
            worst = Math.max(
              worst,
              maxDiff(gotR.P, wantR.P),
              derivDiff(
                wantR,
                gotR.dPdu.map((x) => -x),
                gotR.dPdv,
              ),
            );
          }
      }
      if (process.env.CREASE_REPORT) console.log(`σ ${sigma}: worst |Δ| / diag = ${(worst / diag).toExponential(2)}`);
      expect(worst).toBeLessThanOrEqual(TOL);
    });
    it(`sharpness ${sigma}: loop across v (crease on the face's v = 0 side, patch transposed)`, () => {
      // Crease loop B runs around the major circle through j = J0; faces (i, J0) have it on v = 0.
      // Transposing the grid puts it at u' = 0: (u', v') = (v, u), dP/du' = dP/dv, N' = -N.
      const creases: [number, number, number][] = [];
      for (let i = 0; i < NI; i++) creases.push([idx(i, J0), idx(i + 1, J0), sigma]);
      const S = new Surface(makeCage(torusPos, torusFaces, { creases }));
      let worst = 0;
      for (const i of [1, 6]) {
        const cpT = patchFrom((c, r) => idx(i - 1 + r, J0 - 1 + c));
        for (const u of US)
          for (const v of VS) {
            const want = S.evaluate(faceId(i, J0), v, u);
            const got = evalCreasePatch(cpT, sigma, u, v);
            worst = Math.max(worst, maxDiff(got.P, want.P), derivDiff(want, got.dPdv, got.dPdu));
            expect(
              maxDiff(
                got.N.map((x) => -x),
                want.N,
              ),
              `N at (${u}, ${v})`,
            ).toBeLessThanOrEqual(1e-10);
          }
      }
      if (process.env.CREASE_REPORT) console.log(`σ ${sigma}: worst |Δ| / diag = ${(worst / diag).toExponential(2)}`);
      expect(worst).toBeLessThanOrEqual(TOL);
    });
  }

  it('tolerance sanity: the smooth B-spline is not the answer for a sharp crease', () => {
    // Guards the comparison itself: σ = 2.7 and σ = 0 differ by far more than TOL near the crease.
    const cp = patchFrom((c, r) => idx(I0 - 1 + c, r - 1));
    expect(maxDiff(evalCreasePatch(cp, 2.7, 0.01, 0.5).P, evalCreasePatch(cp, 0, 0.01, 0.5).P)).toBeGreaterThan(1e4 * TOL);
  });
});

/**
 * Independent 1D reference: refine the row L times with the crease vertex rule at b1
 * (sharp while the remaining sharpness s ≥ 1, s·sharp + (1−s)·smooth for 0 < s < 1, smooth
 * at 0; s ← fround(s − 1), as OpenSubdiv decrements), midpoint edge rule, smooth B-spline
 * vertex rule elsewhere; then the uniform B-spline of the level-L polygon. Scalars.
 */
function refineRow(sigma: number, b: number[], L: number, u: number): { P: number; dP: number } {
  let s = Math.fround(sigma);
  let p = b.slice();
  for (let l = 0; l < L; l++) {
    const q: number[] = [];
    for (let i = 0; i + 1 < p.length; i++) {
      if (i > 0) {
        const smooth = (p[i - 1] + 6 * p[i] + p[i + 1]) / 8;
        const sharp = i === 1 ? Math.min(s, 1) : 0; // b1 stays at index 1 at every level
        q.push(sharp * p[i] + (1 - sharp) * smooth);
      }
      q.push((p[i] + p[i + 1]) / 2);
    }
    p = q;
    s = s > 1 ? Math.fround(s - 1) : 0;
  }
  const n = 2 ** L;
  const m = Math.min(Math.floor(u * n), n - 1),
    t = u * n - m;
  const B = [(1 - t) ** 3 / 6, (3 * t ** 3 - 6 * t * t + 4) / 6, (-3 * t ** 3 + 3 * t * t + 3 * t + 1) / 6, t ** 3 / 6];
  const D = [-0.5 * (1 - t) ** 2, 0.5 * (3 * t * t - 4 * t), 0.5 * (-3 * t * t + 2 * t + 1), 0.5 * t * t];
  let P = 0,
    dP = 0;
  for (let i = 0; i < 4; i++) {
    P += B[i] * p[m + i];
    dP += n * D[i] * p[m + i];
  }
  return { P, dP };
}

describe('crease row weights', () => {
  it('equal 1D refinement of each unit row (finite sharpness, decayed to smooth)', () => {
    for (const sigma of [0, 0.25, 0.5, 1, 1.5, 2, 2.3, 2.7, 3.7, 5, 7.9]) {
      const L = Math.ceil(Math.fround(sigma)) + 3;
      for (let x = 0; x <= 64; x++) {
        const u = x / 64 + (x % 3 === 1 ? 1e-3 : 0) * (x < 64 ? 1 : 0);
        const w = creaseRowWeights(sigma, u);
        for (let i = 0; i < 4; i++) {
          const e = [0, 0, 0, 0];
          e[i] = 1;
          const ref = refineRow(sigma, e, L, u);
          expect(Math.abs(w.value[i] - ref.P), `σ ${sigma} u ${u} w${i}`).toBeLessThanOrEqual(1e-14);
          expect(Math.abs(w.du[i] - ref.dP), `σ ${sigma} u ${u} dw${i}`).toBeLessThanOrEqual(1e-12);
        }
      }
    }
  });

  it('form a partition of unity and are bounded (|w| ≤ 2), also for deep levels', () => {
    for (const sigma of [0, 0.5, 3.7, 8.25, 9, 9.99, 10, 50]) {
      for (const u of [0, 1e-6, 2 ** -11, 2 ** -10, 0.001, 0.3, 1]) {
        const w = creaseRowWeights(sigma, u);
        expect(Math.abs(w.value.reduce((a, b) => a + b) - 1)).toBeLessThanOrEqual(1e-15);
        expect(Math.abs(w.du.reduce((a, b) => a + b))).toBeLessThanOrEqual(1e-15);
        for (let i = 0; i < 4; i++) {
          expect(Math.abs(w.value[i])).toBeLessThanOrEqual(2);
          expect(Math.abs(w.du[i])).toBeLessThanOrEqual(2);
        }
      }
    }
  });

  it('on the crease, integer σ = k gives b1 + 2^-k (b0 − 2 b1 + b2)/6 (z = 1 − 1/(3·2^k) for the row (−1, 1, 1, 1))', () => {
    for (let k = 0; k <= 9; k++) {
      const w = creaseRowWeights(k, 0);
      const r = 2 ** -k;
      expect(maxDiff(w.value, [r / 6, 1 - r / 3, r / 6, 0])).toBeLessThanOrEqual(2e-16);
      expect(Math.abs(evalCreaseRow(k, 0, [-1, 1, 1, 1]).P[0] - (1 - 1 / (3 * 2 ** k)))).toBeLessThanOrEqual(4e-16);
    }
    // σ = 0 is the uniform B-spline: (b0 + 4 b1 + b2)/6 on the crease, (b1 + 4 b2 + b3)/6 at u = 1.
    expect(maxDiff(creaseRowWeights(0, 1).value, [0, 1 / 6, 2 / 3, 1 / 6])).toBeLessThanOrEqual(2e-16);
    // σ ≥ 10: interpolates b1 with tangent b2 − b1 (the phantom row 2 b1 − b2).
    expect(Array.from(creaseRowWeights(10, 0).value)).toEqual([0, 1, 0, 0]);
    expect(Array.from(creaseRowWeights(10, 0).du)).toEqual([0, -1, 1, 0]);
    expect(Array.from(creaseRowWeights(1e6, 0.5).value)).toEqual(Array.from(creaseRowWeights(10, 0.5).value));
  });

  it('evaluates vector rows of any dimension and both array types', () => {
    const row = [0, 0, 0, 1, 2, 3, 4, 4, 4, -1, 0, 7];
    const a = evalCreaseRow(2.3, 0.1, row),
      b = evalCreaseRow(2.3, 0.1, Float64Array.from(row));
    expect(a).toEqual(b);
    const w = creaseRowWeights(2.3, 0.1);
    for (let c = 0; c < 3; c++) {
      expect(a.P[c]).toBeCloseTo(w.value[0] * row[c] + w.value[1] * row[3 + c] + w.value[2] * row[6 + c] + w.value[3] * row[9 + c], 15);
    }
    expect(() => evalCreaseRow(1, 0.5, [1, 2, 3])).toThrow(RangeError);
  });

  it('is affine in the fractional part: W(k + f) = (1 − f) W(k) + f W(k + 1), for k + 1 < 10', () => {
    // Not across 10: σ = 10 is infinitely sharp, not "10 sharp levels", so 9 < σ < 10 is no blend of 9 and 10.
    for (const sigma of [0.5, 2.3, 3.7, 8.5]) {
      const s = Math.fround(sigma),
        k = Math.floor(s),
        f = s - k;
      for (let x = 0; x <= 200; x++) {
        const u = (x / 200) ** 3; // dense near the crease
        const w = creaseRowWeights(sigma, u),
          a = creaseRowWeights(k, u),
          b = creaseRowWeights(k + 1, u);
        for (let i = 0; i < 4; i++) {
          expect(Math.abs(w.value[i] - ((1 - f) * a.value[i] + f * b.value[i]))).toBeLessThanOrEqual(1e-15);
          expect(Math.abs(w.du[i] - ((1 - f) * a.du[i] + f * b.du[i]))).toBeLessThanOrEqual(1e-14);
        }
      }
    }
  });

  it('reads σ as float32, as OpenSubdiv stores it', () => {
    // 2.3 in f64 and fround(2.3) are different numbers; both must give the f32 weights.
    const u = 0.05;
    expect(Array.from(creaseRowWeights(2.3, u).value)).toEqual(Array.from(creaseRowWeights(Math.fround(2.3), u).value));
    expect(Array.from(creaseRowWeights(-1, u).value)).toEqual(Array.from(creaseRowWeights(0, u).value));
  });
});
