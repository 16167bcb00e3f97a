import { describe, expect, it } from 'vitest';
import { makeCage } from '../../src/mesh/index.ts';
import { Surface, bsplineBasis, evalBSplinePatch, levelFromCage, limitPositions, refine, refineUniform } from '../../src/subdiv/index.ts';
import { cube, fan, grid3, pentPrism, ringCrease, tetra, triPrism } from '../support/subdiv-fixtures.ts';

type V = ArrayLike<number>;
const close = (a: V, b: V, tol = 1e-13): void => {
  for (let i = 0; i < b.length; i++) expect(Math.abs(a[i] - b[i]), `component ${i}: ${a[i]} vs ${b[i]}`).toBeLessThanOrEqual(tol);
};

describe('smooth cube [-1,1]^3 (values from OpenSubdiv 3.5)', () => {
  const S = new Surface(cube());
  const cases: [number, number, V][] = [
    [0.5, 0.5, [0, 0, 68 / 81]],
    [0, 0, [-0.5, -0.5, 0.5]],
    [0.5, 0, [0, -395 / 648, 395 / 648]],
    [0.25, 0.25, [-0.316157085905, -0.316157085905, 45349 / 62208]],
    [0.5, 0.25, [0, -1727 / 5184, 1351 / 1728]],
    [0.25, 0, [-9227 / 31104, -35641 / 62208, 35641 / 62208]],
    [0.125, 0.0625, [-0.422606066585, -0.486964624769, 0.575952799395]],
    [0.0371, 0.0123, [-0.483857760703, -0.501485750038, 0.514046082809]],
    [2 ** -9, 2 ** -10, [-0.499650065619, -0.499958884521, 0.500390660013]],
  ];
  for (const [u, v, P] of cases) it(`f0 (${u}, ${v})`, () => close(S.evaluate(0, u, v).P, P, 2e-12));
  it('normals at the centre and at the valence-3 corner', () => {
    close(S.evaluate(0, 0.5, 0.5).N, [0, 0, 1]);
    const r = 1 / Math.sqrt(3);
    close(S.evaluate(0, 0, 0).N, [-r, -r, r]);
  });
  it('face centre of [-1/2,1/2]^3 has |P| = 34/81', () => {
    const s = new Surface(cube({}, 0.5));
    for (let f = 0; f < 6; f++) expect(Math.hypot(...s.evaluate(f, 0.5, 0.5).P)).toBeCloseTo(34 / 81, 14);
  });
  it('has octahedral symmetry of |P| across all faces and orientations', () => {
    for (const [u, v] of [
      [0.3, 0.1],
      [0.77, 0.41],
    ]) {
      const ref = Math.hypot(...S.evaluate(0, u, v).P);
      for (let f = 0; f < 6; f++) {
        for (const [a, b] of [
          [u, v],
          [1 - v, u],
          [1 - u, 1 - v],
          [v, 1 - u],
          [v, u],
        ]) {
          expect(Math.hypot(...S.evaluate(f, a, b).P)).toBeCloseTo(ref, 13);
        }
      }
    }
  });
  it('shared edges agree from both faces', () => {
    // f0 (t, 0) is edge v4-v5; f2 = [0,1,5,4] has that edge at (1-t, 1).
    for (const t of [0.1, 0.5, 0.9]) close(S.evaluate(0, t, 0).P, S.evaluate(2, t, 1).P, 1e-15);
  });
});

describe('semi-sharp creases (ring of four top edges)', () => {
  const table: [number, V, V, V, V][] = [
    [0.5, [-107 / 192, -107 / 192, 5 / 8], [0, -445 / 648, 935 / 1296], [0, 0, 149 / 162], [0, -371 / 432, 17 / 648]],
    [1, [-59 / 96, -59 / 96, 3 / 4], [0, -55 / 72, 5 / 6], [0, 0, 1], [0, -569 / 648, 17 / 324]],
    [2, [-125 / 192, -125 / 192, 7 / 8], [0, -121 / 144, 11 / 12], [0, 0, 1], [0, -569 / 648, 17 / 324]],
    [3, [-339 / 512, -339 / 512, 15 / 16], [0, -253 / 288, 23 / 24], [0, 0, 1], [0, -569 / 648, 17 / 324]],
    [10, [-2 / 3, -2 / 3, 1], [0, -11 / 12, 1], [0, 0, 1], [0, -569 / 648, 17 / 324]],
  ];
  for (const [s, c00, c50, ctr, front] of table) {
    it(`sharpness ${s}`, () => {
      const S = new Surface(cube({ creases: ringCrease(s) }));
      close(S.evaluate(0, 0, 0).P, c00);
      close(S.evaluate(0, 0.5, 0).P, c50);
      close(S.evaluate(0, 0.5, 0.5).P, ctr);
      close(S.evaluate(2, 0.5, 0.5).P, front);
    });
  }
  it('more ring values', () => {
    close(new Surface(cube({ creases: ringCrease(1) })).evaluate(0, 0.25, 0.25).P, [-17225 / 41472, -17225 / 41472, 1243 / 1296]);
    close(new Surface(cube({ creases: ringCrease(2) })).evaluate(0, 0.25, 0.25).P, [-31 / 72, -31 / 72, 1]);
    close(new Surface(cube({ creases: ringCrease(2) })).evaluate(2, 0.5, 0.75).P, [0, -4727 / 5184, 1313 / 2592]);
  });
  it('integer sharpness k: corner z = 1 - 2^-(k+1), edge midpoint z = 1 - 1/(3 2^k)', () => {
    for (let k = 1; k <= 6; k++) {
      const S = new Surface(cube({ creases: ringCrease(k) }));
      expect(S.evaluate(0, 0, 0).P[2]).toBeCloseTo(1 - 2 ** -(k + 1), 14);
      expect(S.evaluate(0, 0.5, 0).P[2]).toBeCloseTo(1 - 1 / (3 * 2 ** k), 14);
    }
  });
  it('is affine in the fractional part of the sharpness', () => {
    const f = Math.fround(2.3) - 2;
    const P = (s: number): V =>
      new Surface(
        cube({
          creases: [
            [4, 5, s],
            [5, 6, s],
          ],
          corners: [[0, s]],
        }),
      ).evaluate(0, 0.3, 0.2).P;
    const a = P(2),
      b = P(3),
      c = P(2.3);
    close(
      c,
      [0, 1, 2].map((i) => (1 - f) * a[i] + f * b[i]),
      1e-15,
    );
  });
});

describe('single crease on edge v4-v5 and corner sharpness', () => {
  const rows: [number, V, V, V | null][] = [
    [0.5, [0, -1 / 72, 553 / 648], [0, -431 / 648, 431 / 648], [-0.5, -25 / 48, 25 / 48]],
    [1, [0, -1 / 36, 281 / 324], [0, -467 / 648, 467 / 648], [-0.5, -13 / 24, 13 / 24]],
    [2, [0, -1 / 36, 281 / 324], [0, -1019 / 1296, 1019 / 1296], [-857 / 1728, -1921 / 3456, 1921 / 3456]],
    [3, [0, -1 / 36, 281 / 324], [0, -2123 / 2592, 2123 / 2592], [-0.493067611883, -0.561155719522, 0.561155719522]],
    [10, [0, -1 / 36, 281 / 324], [0, -23 / 27, 23 / 27], null],
  ];
  for (const [s, ctr, mid, dart] of rows) {
    it(`sharpness ${s}`, () => {
      const S = new Surface(cube({ creases: [[4, 5, s]] }));
      close(S.evaluate(0, 0.5, 0.5).P, ctr);
      close(S.evaluate(0, 0.5, 0).P, mid);
      if (dart) close(S.evaluate(0, 0, 0).P, dart, 2e-12);
    });
  }
  it('infinitely sharp: one-sided normals along the crease', () => {
    const S = new Surface(cube({ creases: [[4, 5, 10]] }));
    close(S.evaluate(0, 0.5, 0).N, [0, -0.075867666, 0.997117895], 1e-9);
    close(S.evaluate(2, 0.5, 1).N, [0, -0.997117895, 0.075867666], 1e-9);
  });
  it("infinitely sharp dart: our exact limit is near OpenSubdiv's level-10 value", () => {
    const P = new Surface(cube({ creases: [[4, 5, 10]] })).evaluate(0, 0, 0).P;
    close(P, [-0.490015244945, -0.564984450121, 0.564984450121], 1e-4);
  });
  it('corner sharpness on v6', () => {
    const S2 = new Surface(cube({ corners: [[6, 2]] }));
    close(S2.evaluate(0, 1, 1).P, [25 / 32, 25 / 32, 25 / 32]);
    close(S2.evaluate(0, 0.5, 0.5).P, [1 / 81, 1 / 81, 23 / 27]);
    close(S2.evaluate(0, 0.5, 0.25).P, [1 / 648, -191 / 576, 4061 / 5184]);
    const Si = new Surface(cube({ corners: [[6, 10]] }));
    close(Si.evaluate(0, 1, 1).P, [1, 1, 1]);
    close(Si.evaluate(0, 0.5, 0.5).P, [1 / 81, 1 / 81, 23 / 27]);
  });
});

describe('valence-n fans, boundaries, planar cages', () => {
  for (const n of [3, 5, 6, 8]) {
    it(`apex of a valence-${n} fan is at n/(n+5)`, () => {
      const r = new Surface(fan(n)).evaluate(0, 0, 0);
      close(r.P, [0, 0, n / (n + 5)]);
      close(r.N, [0, 0, 1], 1e-12);
    });
  }
  it('grid3 boundary curve is the cubic B-spline of the boundary vertices', () => {
    const S = new Surface(grid3());
    close(S.evaluate(0, 0, 0).P, [0, 0, 0]);
    close(S.evaluate(0, 0.5, 0).P, [0.5, 0, 11 / 24]);
    close(S.evaluate(0, 1, 0).P, [1, 0, 2 / 3]);
    close(S.evaluate(1, 0.5, 0).P, [1.5, 0, 25 / 48]);
    close(S.evaluate(0, 0, 0.5).P, [0, 0.5, 11 / 24]);
    close(S.evaluate(8, 1, 1).P, [3, 3, 0]);
    close(S.evaluate(4, 0.5, 0.5).P, [1.5, 1.5, 541 / 288]);
  });
  it('an infinitely sharp crease edge follows the cubic B-spline of its crease vertices', () => {
    // Crease along the middle row of a 5x5 grid (j = 2), bumpy heights.
    const p: number[] = [];
    const h = (i: number, j: number): number => Math.sin(1.3 * i + 0.7 * j) + 0.3 * j;
    for (let j = 0; j < 5; j++) for (let i = 0; i < 5; i++) p.push(i, j, h(i, j));
    const f: number[][] = [];
    for (let j = 0; j < 4; j++) for (let i = 0; i < 4; i++) f.push([5 * j + i, 5 * j + i + 1, 5 * j + i + 6, 5 * j + i + 5]);
    const creases: [number, number, number][] = [];
    for (let i = 0; i < 4; i++) creases.push([10 + i, 11 + i, 10]);
    const S = new Surface(makeCage(p, f, { creases }));
    // Face 5 = [6,7,12,11] has the crease (vertices 11,12 of row j=2) on its side 2 (v = 1).
    const b = [0, 1, 2, 3].map((i) => [i, 2, h(i, 2)]);
    const bb = [0, 0, 0, 0],
      db = [0, 0, 0, 0];
    for (const t of [0, 0.25, 0.5, 0.8, 1]) {
      bsplineBasis(t, bb, db);
      // Segment between b1 and b2, with phantom-free interior vertices b0..b3.
      const want = [0, 1, 2].map((c) => bb[0] * b[0][c] + bb[1] * b[1][c] + bb[2] * b[2][c] + bb[3] * b[3][c]);
      close(S.evaluate(5, t, 1).P, want, 1e-14);
    }
  });
  it('a planar cage stays planar', () => {
    let seed = 7;
    const rnd = (): number => (seed = (seed * 16807) % 2147483647) / 2147483647 - 0.5;
    const p: number[] = [];
    for (let j = 0; j < 4; j++) for (let i = 0; i < 4; i++) p.push(i + 0.3 * rnd(), j + 0.3 * rnd(), 0);
    const f: number[][] = [];
    for (let j = 0; j < 3; j++) for (let i = 0; i < 3; i++) f.push([4 * j + i, 4 * j + i + 1, 4 * j + i + 5, 4 * j + i + 4]);
    const S = new Surface(makeCage(p, f));
    for (let k = 0; k < 9; k++)
      for (const [u, v] of [
        [0, 0],
        [0.3, 0.9],
        [1, 0.5],
        [0.5, 0.5],
      ]) {
        const r = S.evaluate(k, u, v);
        expect(r.P[2]).toBe(0);
        expect(Math.abs(r.N[2])).toBe(1);
      }
  });
});

describe('regular patches are bicubic B-splines', () => {
  it('interior face of a 4x4 regular region equals the tensor-product formula', () => {
    // Torus-like closed 6x6 grid makes every vertex valence 4 (periodic), heights random.
    const n = 6;
    const p: number[] = [];
    const H = (i: number, j: number): number => Math.cos(i * 1.1) * Math.sin(j * 0.9 + 0.2) + 0.1 * i * ((i + j) % 3);
    for (let j = 0; j < n; j++)
      for (let i = 0; i < n; i++) {
        const a = (2 * Math.PI * i) / n,
          b = (2 * Math.PI * j) / n;
        const R = 3 + (1 + 0.2 * H(i, j)) * Math.cos(b);
        p.push(R * Math.cos(a), R * Math.sin(a), (1 + 0.2 * H(i, j)) * Math.sin(b));
      }
    const id = (i: number, j: number): number => ((j + n) % n) * n + ((i + n) % n);
    const f: number[][] = [];
    for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) f.push([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
    const S = new Surface(makeCage(p, f));
    const i0 = 2,
      j0 = 3;
    const cp = new Float64Array(48);
    for (let r = 0; r < 4; r++)
      for (let c = 0; c < 4; c++) {
        const v = id(i0 - 1 + c, j0 - 1 + r);
        cp.set(p.slice(3 * v, 3 * v + 3), 3 * (4 * r + c));
      }
    const out = new Float64Array(9);
    for (const [u, v] of [
      [0.1, 0.2],
      [0.5, 0.5],
      [0.93, 0.07],
      [1, 1],
    ]) {
      evalBSplinePatch(cp, u, v, out);
      const r = S.evaluate(id(i0, j0), u, v);
      close(r.P, out.subarray(0, 3), 1e-14);
      close(r.dPdu, out.subarray(3, 6), 1e-13);
      close(r.dPdv, out.subarray(6, 9), 1e-13);
    }
  });
});

describe('triangles and n-gons (sub-face parameterisation)', () => {
  it('tetrahedron', () => {
    const S = new Surface(tetra());
    close(S.evaluateSubFace(0, 0, 0, 0).P, [2 / 9, 2 / 9, 2 / 9]);
    close(S.evaluateSubFace(0, 0, 1, 1).P, [20 / 81, 20 / 81, -20 / 81]);
    close(S.evaluateSubFace(0, 0, 1, 0).P, [104 / 243, 0, 0]);
    close(S.evaluateSubFace(0, 0, 0.5, 0.5).P, [20249 / 69984, 20249 / 69984, -133 / 8748]);
    close(S.evaluateSubFace(0, 1, 0.5, 0.5).P, [20249 / 69984, 133 / 8748, -20249 / 69984]);
  });
  it('triangular prism', () => {
    const S = new Surface(triPrism());
    const r3 = Math.sqrt(3);
    close(S.evaluateSubFace(0, 0, 1, 1).P, [0, 0, 59 / 72]);
    close(S.evaluateSubFace(0, 0, 0, 0).P, [1 / 3, 0, 0.5]);
    close(S.evaluateSubFace(0, 1, 1, 0).P, [-353 / 1296, 0, 395 / 648]);
    close(S.evaluate(2, 0.5, 0.5).P, [257 / 1296, (257 * r3) / 1296, 0]);
    close(S.evaluate(2, 0.5, 0).P, [353 / 2592, (353 * r3) / 2592, -395 / 648]);
  });
  it('pentagonal prism (valence-5 centre)', () => {
    const S = new Surface(pentPrism());
    for (let k = 0; k < 5; k++) close(S.evaluateSubFace(0, k, 1, 1).P, [0, 0, 77 / 90]);
    close(S.evaluateSubFace(0, 0, 0, 0).P, [0.603005664792, 0, 0.5], 1e-12);
    close(S.evaluateSubFace(0, 0, 1, 0).P, [0.425185514307, 0.308915358436, 395 / 648], 1e-12);
    close(S.evaluateSubFace(0, 3, 0.5, 0.5).P, [-0.326831627794, -0.23745707709, 45391 / 62208], 1e-12);
    close(S.evaluateSubFace(0, 0, 0.9375, 0.96875).P, [0.056149141187, -0.014802599143, 0.852893544996], 1e-12);
    close(S.evaluateSubFace(0, 0, 0.9629, 0.9877).P, [0.032784258315, -0.012812178705, 0.854528524314], 1e-12);
    close(S.evaluateSubFace(0, 0, 0.99609375, 0.998046875).P, [0.005139707961, -0.001354839743, 0.855526900906], 1e-12);
    close(S.evaluate(2, 0.5, 0.5).P, [0.568191168805, 0.412815048174, 0], 1e-12);
  });
});

describe('consistency', () => {
  const cages = {
    cube: cube({
      creases: [
        [4, 5, 2.3],
        [5, 6, 10],
      ],
      corners: [[0, 1.5]],
    }),
    pentPrism: pentPrism(),
    triPrism: triPrism(),
    grid3: grid3(),
  };
  for (const [name, cage] of Object.entries(cages)) {
    it(`${name}: vertex limits at levels 0..2 equal evaluation at their (u,v)`, () => {
      const S = new Surface(cage);
      let L = levelFromCage(cage);
      // Track, for every face of the current level, the cage face, sub-face and its corners' (s,t).
      type Param = { f: number; k: number; c: [number, number][] };
      let params: Param[] = [];
      for (let f = 0; f < L.he.nFaces; f++) {
        const n = L.he.faceOffsets[f + 1] - L.he.faceOffsets[f];
        params.push({
          f,
          k: -1,
          c:
            n === 4
              ? [
                  [0, 0],
                  [1, 0],
                  [1, 1],
                  [0, 1],
                ]
              : [],
        });
      }
      for (let level = 0; level <= 2; level++) {
        const lim = limitPositions(L);
        for (let f = 0; f < L.he.nFaces; f++) {
          const pr = params[f];
          if (!pr.c.length) continue;
          for (let j = 0; j < 4; j++) {
            const v = L.he.faceIndices[L.he.faceOffsets[f] + j];
            const [s, t] = pr.c[j];
            const r = pr.k < 0 ? S.evaluate(pr.f, s, t) : S.evaluateSubFace(pr.f, pr.k, s, t);
            close(r.P, lim.P.subarray(3 * v, 3 * v + 3), 1e-13);
          }
        }
        const C = refine(L);
        const next: Param[] = [];
        for (let h = 0; h < C.he.nFaces; h++) {
          const pf = C.faceParent![h],
            j = C.faceCorner![h];
          const pr = params[pf];
          const n = L.he.faceOffsets[pf + 1] - L.he.faceOffsets[pf];
          if (!pr.c.length) {
            // Child j of a cage n-gon is sub-face j.
            next.push({
              f: pr.f,
              k: j,
              c: [
                [0, 0],
                [1, 0],
                [1, 1],
                [0, 1],
              ],
            });
            continue;
          }
          const mid = (a: [number, number], b: [number, number]): [number, number] => [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
          const c = pr.c;
          const ctr = mid(mid(c[0], c[1]), mid(c[2], c[3]));
          next.push({ f: pr.f, k: pr.k, c: [c[j], mid(c[j], c[(j + 1) % n]), ctr, mid(c[(j + n - 1) % n], c[j])] });
        }
        L = C;
        params = next;
      }
    });
  }
  it('derivatives agree with finite differences', () => {
    for (const cage of [cube({ creases: [[4, 5, 1.7]] }), pentPrism()]) {
      const S = new Surface(cage);
      const h = 1e-6;
      for (const [f, k, s, t] of [
        [0, 0, 0.3, 0.4],
        [2, 0, 0.61, 0.27],
        [0, 0, 0.05, 0.9],
      ]) {
        const n = S.faceSize(f);
        const ev = (a: number, b: number): V => (n === 4 ? S.evaluate(f, a, b) : S.evaluateSubFace(f, k, a, b)).P;
        const r = n === 4 ? S.evaluate(f, s, t) : S.evaluateSubFace(f, k, s, t);
        const du = [0, 1, 2].map((c) => (ev(s + h, t)[c] - ev(s - h, t)[c]) / (2 * h));
        const dv = [0, 1, 2].map((c) => (ev(s, t + h)[c] - ev(s, t - h)[c]) / (2 * h));
        close(r.dPdu, du, 1e-7);
        close(r.dPdv, dv, 1e-7);
      }
    }
  });
  it('uniform refinement keeps face counts and refine(L) preserves provenance', () => {
    const L = refineUniform(levelFromCage(pentPrism()), 2);
    expect(L.he.nFaces).toBe(4 * (10 + 5 * 4));
  });
});
