/**
 * The ACC yardstick (src/subdiv/acc.ts) against the test values of the papers and the NVIDIA sample:
 * constants, cube reference vectors, corners = CC limit, symmetry, affine invariance, planar cage,
 * regular exactness, across-edge continuity (and that the geometry-patch normals of Bezier ACC do
 * jump, so the continuity check can fail), the Gregory triangle blend on an octahedron.
 */
import { describe, it, expect } from 'vitest';
import { loadCage, makeCage, type Cage } from '../../../src/mesh/index.ts';
import {
  ACC_SCHEMES,
  AccError,
  KIND_BEZIER,
  KIND_PM_TRI_LS,
  KIND_REGULAR,
  SECTOR_CORNER,
  SECTOR_CREASE,
  valenceConstants,
} from '../../../src/subdiv/acc.ts';
import { type V3, cross3 } from '../../../src/subdiv/acc-patches.ts';
import { AccSurface, evalBicubic, evalTangentPatches } from '../../../src/subdiv/acc-evaluate.ts';
import {
  ExactAt,
  accErrors,
  bboxDiagonal,
  boundaryCages,
  ccStep,
  continuity,
  edgeParam,
  octahedron,
  prism,
  randomFaceParams,
  smoothEdges,
  valence2Cube,
} from '../../support/acc-checks.ts';
import { cube, triPrism } from '../../support/subdiv-fixtures.ts';
import { accFaceParam } from '../../../src/gpu/acc/patches.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import creature from '../../../public/models/creature.obj?raw';
import torus from '../../../public/models/torus.obj?raw';
import icosphere from '../../../public/models/icosphere.obj?raw';
import sheet from '../../../public/models/sheet.obj?raw';
import creasedBox from '../../../public/models/creased-box.obj?raw';

const close = (a: ArrayLike<number>, b: ArrayLike<number>, tol: number) => {
  for (let i = 0; i < a.length; i++)
    expect(Math.abs(a[i] - b[i]), `component ${i}: ${Array.from(a)} vs ${Array.from(b)}`).toBeLessThanOrEqual(tol);
};
const dist = (a: V3, b: V3) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
const creatureCage = loadCage(creature).cage;
const exactCreature = new ExactAt(creatureCage);
/** The face of the cube with corners (−1,−1,1), (1,−1,1), (1,1,1), (−1,1,1) as P0..P3. */
const cubeTop = () => {
  const c = cube();
  const S = (s: (typeof ACC_SCHEMES)[number]) => new AccSurface(c, s);
  return { c, S, face: 0 }; // cube() face 0 is [4,5,6,7]
};

describe('constants', () => {
  it('λ_n, 1/(nλ_n), σ_4, the n = 4 masks', () => {
    expect(valenceConstants(3).lambda).toBeCloseTo(0.410097, 6);
    expect(valenceConstants(5).lambda).toBeCloseTo(0.549988, 6);
    expect(valenceConstants(6).lambda).toBeCloseTo(0.579682, 6);
    expect(valenceConstants(4).lambda).toBe(0.5);
    expect(1 / (3 * valenceConstants(3).lambda)).toBeCloseTo(0.812816, 6);
    expect(valenceConstants(4).sigma).toBeCloseTo(0.471405, 6);
    close(valenceConstants(4).alpha, [1 / 3, 0, -1 / 3, 0], 1e-15);
    close(valenceConstants(4).beta, [1 / 12, -1 / 12, -1 / 12, 1 / 12], 1e-15);
  });
  it('the Loop–Schaefer mask has the exact CC tangent direction (e/D weight ratio = Sdc’s)', () => {
    const ratioLS = (n: number) => {
      const k = valenceConstants(n);
      return (1 + k.sigma * Math.cos(Math.PI / n)) / k.sigma;
    };
    const ratioSdc = (n: number) => (2 * (4 * valenceConstants(n).lambda - 1)) / Math.cos(Math.PI / n);
    expect(ratioLS(3)).toBeCloseTo(2.5616, 4);
    expect(ratioLS(5)).toBeCloseTo(2.9664, 4);
    for (let n = 3; n <= 16; n++) expect(Math.abs(ratioLS(n) - ratioSdc(n))).toBeLessThan(1e-12);
  });
  it('position stencils sum to 1, tangent masks to 0', () => {
    for (let n = 3; n <= 12; n++) {
      const k = valenceConstants(n);
      expect(Math.abs(k.alpha.reduce((a, b) => a + b, 0))).toBeLessThan(1e-14);
      expect(Math.abs(k.beta.reduce((a, b) => a + b, 0))).toBeLessThan(1e-14);
      expect(Math.abs(k.cosk.reduce((a, b) => a + b, 0))).toBeLessThan(1e-14);
    }
  });
});

describe('cube reference vectors (values measured for this project)', () => {
  const { S, face } = cubeTop();
  it('Bezier ACC: geometry and tangent patches', () => {
    const q = S('bezier-acc').patch(face);
    expect(S('bezier-acc').kind(face)).toBe(KIND_BEZIER);
    close(q[0], [-0.5, -0.5, 0.5], 1e-15); // b00 = corner = CC limit
    close(q[1], [-0.25, -0.625, 0.625], 1e-15); // b10
    close(q[5], [-0.25, -0.25, 1], 1e-15); // b11
    close(q[16], [1.151738, -0.575869, 0.575869], 1e-6); // U_{0,0}
    close(q[17], [1.029022, -0.308044, 1.220978], 1e-6); // U_{0,1}
    for (let c = 0; c < 4; c++) close(mulv(sub(q[2 + 4 * c], q[1 + 4 * c]), 3), [1.5, 0, 0], 1e-15); // U_{1,c} = 3(b_2c − b_1c)
    const centre = S('bezier-acc').evaluate(face, 0.5, 0.5);
    close(centre.P, [0, 0, 53 / 64], 1e-15);
    close(centre.N, [0, 0, 1], 1e-15);
  });
  it('Gregory ACC: E0⁺, F0⁺ and its mirror F0⁻, centre', () => {
    const q = S('gregory-acc').patch(face);
    close(q[0], [-0.5, -0.5, 0.5], 1e-15);
    close(q[1], [-0.243627, -0.628187, 0.628187], 1e-6);
    close(q[3], [-0.363315, -0.316218, 0.982884], 1e-6);
    close(q[4], [q[3][1], q[3][0], q[3][2]], 1e-15); // mirror across x = y
    const c = S('gregory-acc').evaluate(face, 0.5, 0.5);
    close(c.P, [0, 0, 0.819693], 1e-6);
    close(c.N, [0, 0, 1], 1e-14);
  });
  it('Pm ACC: t0⁺, b211_0, b112_0, centre', () => {
    const q = S('pm-acc').patch(face);
    close(q[0], [-0.5, -0.5, 0.5], 1e-15);
    close(q[1], [-0.229061, -0.635469, 0.635469], 1e-6);
    close(q[3], [-0.18873, -0.482665, 0.77134], 1e-6);
    close(q[5], [0, -0.335697, 0.84375], 1e-6);
    const c = S('pm-acc').evaluate(face, 0.5, 0.5);
    close(c.P, [0, 0, 27 / 32], 1e-15);
    close(c.N, [0, 0, 1], 1e-14);
  });
  it('every corner of every scheme is (±0.5, ±0.5, ±0.5); the exact reference agrees (68/81 at the centre)', () => {
    for (const s of ACC_SCHEMES) {
      const A = S(s);
      for (let f = 0; f < 6; f++)
        for (const [u, v] of [
          [0, 0],
          [1, 0],
          [1, 1],
          [0, 1],
        ]) {
          for (const x of A.evaluate(f, u, v).P) expect(Math.abs(Math.abs(x) - 0.5)).toBeLessThan(1e-15);
        }
    }
    const E = new ExactAt(cube());
    close(E.at(face, 0.5, 0.5).P, [0, 0, 68 / 81], 1e-14);
    close(E.at(face, 0.25, 0.25).P, [-0.316157, -0.316157, 0.72899], 1e-6);
  });
});
const sub = (a: V3, b: V3): V3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const mulv = (a: V3, s: number): V3 => [a[0] * s, a[1] * s, a[2] * s];

describe('n-fold symmetry', () => {
  for (const n of [3, 5, 6, 8]) {
    it(`valence ${n}: corner normal on the axis, E⁺ / t⁺ rotate, F⁺ and F⁻ mirror`, () => {
      const cage = ccStep(prism(n, 0));
      const nV = cage.positions.length / 3;
      // The cap centre at z > 0: valence n, on the z axis.
      let centre = -1;
      for (let v = 0; v < nV; v++)
        if (Math.hypot(cage.positions[3 * v], cage.positions[3 * v + 1]) < 1e-12 && cage.positions[3 * v + 2] > 0) centre = v;
      expect(centre).toBeGreaterThanOrEqual(0);
      const faces: { f: number; k: number }[] = [];
      for (let f = 0; f < cage.faceOffsets.length - 1; f++)
        for (let k = 0; k < 4; k++) if (cage.faceIndices[cage.faceOffsets[f] + k] === centre) faces.push({ f, k });
      expect(faces.length).toBe(n);
      const rot = (p: V3, a: number): V3 => [Math.cos(a) * p[0] - Math.sin(a) * p[1], Math.sin(a) * p[0] + Math.cos(a) * p[1], p[2]];
      for (const s of ACC_SCHEMES) {
        const A = new AccSurface(cage, s);
        for (const { f, k } of faces) {
          const uv = [
            [0, 0],
            [1, 0],
            [1, 1],
            [0, 1],
          ][k];
          const N = A.evaluate(f, uv[0], uv[1]).N;
          expect(Math.hypot(N[0], N[1]), `${s} normal ${N}`).toBeLessThan(1e-12);
        }
        // Edge/tangent point toward the next corner (Gregory E⁺ at 5k+1, Pm t⁺ at 6k+1) and face points.
        const pts = faces.map(({ f, k }) => {
          const q = A.patch(f);
          if (s === 'gregory-acc')
            return { e: q[5 * k + 1], fp: q[5 * k + 3], fm: q[5 * k + 4], opp: cage.faceIndices[cage.faceOffsets[f] + ((k + 2) % 4)] };
          if (s === 'pm-acc') return { e: q[6 * k + 1], fp: null, fm: null, opp: 0 };
          // Bezier: the edge point toward the next corner (b at the corner's next step).
          return { e: q[[1, 7, 14, 8][k]], fp: null, fm: null, opp: 0 };
        });
        for (const a of pts) {
          // Rotating by 2π/n maps the set onto itself.
          const r = rot(a.e, (2 * Math.PI) / n);
          expect(Math.min(...pts.map((b) => dist(b.e, r))), s).toBeLessThan(1e-12);
          if (a.fp && a.fm) {
            // Mirror across the vertical plane through the face's opposite vertex.
            const o = [cage.positions[3 * a.opp], cage.positions[3 * a.opp + 1]];
            const l = Math.hypot(o[0], o[1]),
              d = [o[0] / l, o[1] / l];
            const dot = a.fp[0] * d[0] + a.fp[1] * d[1];
            const m: V3 = [2 * dot * d[0] - a.fp[0], 2 * dot * d[1] - a.fp[1], a.fp[2]];
            expect(dist(m, a.fm)).toBeLessThan(1e-12);
          }
        }
      }
    });
  }
});

describe('affine invariance and planar cages', () => {
  const A = [
      [0.8, 0.3, -0.2],
      [-0.1, 1.2, 0.4],
      [0.25, -0.3, 0.9],
    ],
    t = [3, -2, 5];
  const affine = (p: ArrayLike<number>, lin = false) => {
    const out = new Float64Array(p.length);
    for (let i = 0; i < p.length; i += 3)
      for (let r = 0; r < 3; r++) out[i + r] = A[r][0] * p[i] + A[r][1] * p[i + 1] + A[r][2] * p[i + 2] + (lin ? 0 : t[r]);
    return out;
  };
  for (const s of ACC_SCHEMES) {
    it(`${s}: an affine map of the cage maps every control point (tangent-patch vectors by its linear part)`, () => {
      const S0 = new AccSurface(creatureCage, s);
      const moved = affine(creatureCage.positions);
      const S1 = new AccSurface({ ...creatureCage, positions: moved }, s);
      const scale = bboxDiagonal(moved);
      for (let f = 0; f < S0.topology.nPatches; f++) {
        const q0 = S0.patch(f),
          q1 = S1.patch(f);
        q0.forEach((p, i) => {
          const vector = S0.kind(f) === KIND_BEZIER && i >= 16;
          close(q1[i], affine(p, vector), 1e-12 * scale);
        });
      }
    });
    it(`${s}: a planar cage (z = 0) gives z = 0 control points and ±z normals`, () => {
      const flat = Float64Array.from(creatureCage.positions, (x, i) => (i % 3 === 2 ? 0 : x));
      const S = new AccSurface({ ...creatureCage, positions: flat }, s);
      for (let i = 2; i < S.points.length; i += 3) expect(Math.abs(S.points[i])).toBe(0);
      for (const [f, u, v] of randomFaceParams(creatureCage, 2000)) {
        const N = S.evaluate(f, u, v).N;
        if (!N.every(Number.isFinite)) continue; // folded flat: zero-area spots have no normal
        expect(Math.hypot(N[0], N[1])).toBeLessThan(1e-9);
      }
    });
  }
});

describe('regular exactness', () => {
  const torusCage = loadCage(torus).cage;
  const exact = new ExactAt(torusCage);
  const params = randomFaceParams(torusCage, 400);
  it('every torus patch is REGULAR and equals the exact B-spline limit in every scheme', () => {
    for (const s of ACC_SCHEMES) {
      const S = new AccSurface(torusCage, s);
      for (let f = 0; f < S.topology.nPatches; f++) expect(S.kind(f)).toBe(KIND_REGULAR);
      const e = accErrors(S, exact, params);
      expect(e.maxP).toBeLessThan(1e-14);
      expect(e.maxN).toBeLessThan(1e-5); // degrees (acos of nearly parallel unit vectors)
    }
  });
  it('Bezier construction on regular quads: geometry = B-spline, tangent patches = its exact derivatives', () => {
    const S = new AccSurface(torusCage, 'bezier-acc', undefined, { noRegular: true });
    const R = new AccSurface(torusCage, 'bezier-acc');
    for (const [f, u, v] of params) {
      const q = S.patch(f);
      close(q.slice(0, 16).flat(), R.patch(f).flat(), 1e-14);
      const d = evalBicubic(q, u, v),
        t = evalTangentPatches(q, u, v);
      close(t.Tu, d.Pu, 1e-13);
      close(t.Tv, d.Pv, 1e-13);
    }
  });
  it('Gregory on regular quads: F⁺ = F⁻ and the surface is the bicubic', () => {
    const S = new AccSurface(torusCage, 'gregory-acc', undefined, { noRegular: true });
    for (let f = 0; f < S.topology.nPatches; f++) {
      const q = S.patch(f);
      for (let k = 0; k < 4; k++) close(q[5 * k + 3], q[5 * k + 4], 1e-14);
    }
    expect(accErrors(S, exact, params).maxP).toBeLessThan(1e-14);
  });
  it('guard: the Pm c-patch is NOT exact on regular quads (≈7e-6), so they must be routed to the bicubic', () => {
    const S = new AccSurface(torusCage, 'pm-acc', undefined, { noRegular: true });
    const e = accErrors(S, exact, params);
    expect(e.maxP).toBeGreaterThan(1e-7);
    expect(e.maxP).toBeLessThan(1e-4);
  });
});

describe('corners = Catmull-Clark limit', () => {
  const exact = new ExactAt(creatureCage);
  const cornerParam = (m: number, k: number): [number, number] =>
    m === 4
      ? ([
          [0, 0],
          [1, 0],
          [1, 1],
          [0, 1],
        ][k] as [number, number])
      : ([
          [0, 0],
          [1, 0],
          [0, 1],
        ][k] as [number, number]);
  for (const s of ACC_SCHEMES) {
    it(`${s}: every patch corner ${s === 'pm-acc' ? 'with an all-quad ring ' : ''}is the exact limit (triangles included)`, () => {
      const S = new AccSurface(creatureCage, s);
      const T = S.topology;
      let checked = 0,
        nearTriangle = 0;
      for (let f = 0; f < T.nPatches; f++)
        for (let k = 0; k < T.faceSize[f]; k++) {
          const [u, v] = cornerParam(T.faceSize[f], k);
          const d = dist(S.evaluate(f, u, v).P, exact.at(f, u, v).P);
          const vtx = T.corners[8 * f + 2 * k],
            o = T.ringOffs[vtx],
            n = (T.ringOffs[vtx + 1] - o) / 2;
          const triRing = Array.from(T.ringData.subarray(o + n, o + 2 * n)).some((x) => x === 0xffffffff);
          if (s === 'pm-acc' && triRing) {
            if (d > 1e-6) nearTriangle++;
            continue;
          }
          expect(d, `face ${f} corner ${k}`).toBeLessThan(1e-12);
          checked++;
        }
      expect(checked).toBeGreaterThan(1000);
      // Pm's midpoint rule next to triangles misses the limit: the check can tell.
      if (s === 'pm-acc') expect(nearTriangle).toBeGreaterThan(0);
    });
  }
});

describe('across-edge continuity', () => {
  const cages: [string, Cage][] = [
    ['prism 5 (CC step)', ccStep(prism(5))],
    ['prism 6 (CC step)', ccStep(prism(6))],
    ['prism 8 (CC step)', ccStep(prism(8))],
    ['creature', creatureCage],
    ['triangular prism', triPrism()],
    ['octahedron', octahedron()],
  ];
  for (const [name, cage] of cages) {
    for (const s of ACC_SCHEMES) {
      it(`${name}, ${s}: position gap < 1e-6 of the diagonal; normal jump < 0.01°${s === 'bezier-acc' ? ' between quads (tangent-patch normals)' : ''}`, () => {
        const S = new AccSurface(cage, s);
        const pos = continuity(S);
        expect(pos.edges).toBeGreaterThan(0);
        expect(pos.maxGap).toBeLessThan(1e-6);
        if (s !== 'bezier-acc') {
          expect(pos.maxJumpDeg, pos.worst).toBeLessThan(0.01);
        } else {
          const quads = (f: number) => S.kind(f) !== KIND_PM_TRI_LS;
          const q = continuity(S, undefined, 9, (a, b) => quads(a) && quads(b));
          if (q.edges) expect(q.maxJumpDeg, q.worst).toBeLessThan(0.01);
          // An all-triangle cage is all Pm triangles (no Loop–Schaefer edge): G1 as in pm-acc.
          if (!q.edges) expect(pos.maxJumpDeg, pos.worst).toBeLessThan(0.01);
        }
      });
    }
  }
  it('the Bezier ACC geometry-patch normals DO jump across edges (degrees), so the check can fail', () => {
    for (const cage of [ccStep(prism(5)), creatureCage]) {
      const S = new AccSurface(cage, 'bezier-acc');
      const geo = (f: number, u: number, v: number) => {
        if (S.kind(f) === KIND_PM_TRI_LS) return S.evaluate(f, u, v).N;
        const d = evalBicubic(S.patch(f), u, v);
        return cross3(d.Pu, d.Pv);
      };
      const quads = (f: number) => S.kind(f) !== KIND_PM_TRI_LS;
      const st = continuity(S, geo, 9, (a, b) => quads(a) && quads(b));
      expect(st.maxJumpDeg).toBeGreaterThan(0.5);
    }
  });
});

describe('boundaries, infinitely sharp creases and corners', () => {
  const cages = boundaryCages();
  for (const [name, cage] of cages) {
    const exact = new ExactAt(cage);
    const diag = bboxDiagonal(cage.positions);
    const smooth = smoothEdges(cage);
    for (const s of ACC_SCHEMES) {
      it(`${name}, ${s}: watertight (sharp edges too), G1 across smooth edges, no NaN`, () => {
        const S = new AccSurface(cage, s);
        expect(S.topology.maxSector).toBeGreaterThan(0);
        const all = continuity(S);
        expect(all.edges).toBeGreaterThan(0);
        expect(all.maxGap).toBeLessThan(1e-6);
        // Bezier ACC: between its quads (tangent patches); an all-triangle cage is all Pm triangles.
        const tri = (f: number) => S.kind(f) === KIND_PM_TRI_LS;
        const anyQuad = [...Array(S.topology.nPatches).keys()].some((f) => !tri(f));
        const g1 = continuity(
          S,
          undefined,
          9,
          (fa, fb, a, b) => smooth(fa, fb, a, b) && (s !== 'bezier-acc' || !anyQuad || (!tri(fa) && !tri(fb))),
        );
        expect(g1.edges).toBeGreaterThan(0);
        expect(g1.maxJumpDeg, g1.worst).toBeLessThan(0.01);
        expect(accErrors(S, exact, randomFaceParams(cage, 300, 3)).nan).toBe(0);
      });
    }
    it(`${name}: every scheme interpolates the exact crease/boundary curve between crease and corner vertices, and regular patches are exact`, () => {
      for (const s of ACC_SCHEMES) {
        const S = new AccSurface(cage, s);
        const T = S.topology;
        let checked = 0,
          regular = 0;
        for (let f = 0; f < T.nPatches; f++) {
          const m = T.faceSize[f];
          for (let k = 0; k < m; k++) {
            const k1 = (k + 1) % m;
            const a = T.corners[8 * f + 2 * k],
              b = T.corners[8 * f + 2 * k1];
            const ta = T.sectors[4 * f + k] & 3,
              tb = T.sectors[4 * f + k1] & 3;
            const sharpType = (t: number) => t === SECTOR_CREASE || t === SECTOR_CORNER;
            if (smooth(f, f, a, b) || !sharpType(ta) || !sharpType(tb)) continue;
            for (let i = 0; i <= 4; i++) {
              const [u, v] = edgeParam(m, k, i / 4);
              expect(dist(S.evaluate(f, u, v).P, exact.at(f, u, v).P) / diag, `${s} face ${f} edge ${k}`).toBeLessThan(1e-12);
              checked++;
            }
          }
          if (S.kind(f) === KIND_REGULAR)
            for (const [u, v] of [
              [0.3, 0.6],
              [0.9, 0.1],
            ]) {
              expect(dist(S.evaluate(f, u, v).P, exact.at(f, u, v).P) / diag).toBeLessThan(1e-12);
              regular++;
            }
        }
        expect(checked, s).toBeGreaterThan(0);
        if (name.startsWith('prism')) expect(regular).toBeGreaterThan(0);
      }
    });
  }
  it('an interior vertex of valence 2: built with a warning, watertight, G1 (Gregory, Pm) away from the vertex, no NaN', () => {
    const cage = valence2Cube(cube());
    const exact = new ExactAt(cage);
    for (const s of ACC_SCHEMES) {
      const S = new AccSurface(cage, s);
      expect(S.topology.warnings.join()).toMatch(/valence 2/);
      const st = continuity(S);
      expect(st.maxGap).toBeLessThan(1e-6);
      // The vertex itself has no tangent plane (in Catmull-Clark too): its edges sampled short of it.
      const m = cage.positions.length / 3 - 1;
      const g1 = continuity(S, undefined, 9, (_fa, _fb, a, b) => a !== m && b !== m);
      if (s !== 'bezier-acc') expect(g1.maxJumpDeg, g1.worst).toBeLessThan(0.01);
      expect(accErrors(S, exact, randomFaceParams(cage, 200, 3)).nan).toBe(0);
    }
  });
  it('the Bezier ACC geometry-patch normals DO jump across smooth edges of an open, creased cage', () => {
    const [, cage] = cages[0];
    const S = new AccSurface(cage, 'bezier-acc');
    const smooth = smoothEdges(cage);
    const geo = (f: number, u: number, v: number) => {
      const d = evalBicubic(S.patch(f), u, v);
      return cross3(d.Pu, d.Pv);
    };
    const quads = (f: number) => S.kind(f) !== KIND_PM_TRI_LS;
    const st = continuity(S, geo, 9, (a, b, va, vb) => quads(a) && quads(b) && smooth(a, b, va, vb));
    expect(st.maxJumpDeg).toBeGreaterThan(0.5);
  });
});

describe('errors against exact Catmull-Clark', () => {
  it('cube after one CC step, 9×9 grid per face: reference max position / normal errors measured for this project', () => {
    const cage = ccStep(cube());
    const exact = new ExactAt(cage);
    const params: [number, number, number][] = [];
    for (let f = 0; f < 24; f++) for (let j = 0; j <= 8; j++) for (let i = 0; i <= 8; i++) params.push([f, i / 8, j / 8]);
    const expected: Record<string, [number, number]> = {
      'bezier-acc': [0.0038, 1.79],
      'gregory-acc': [0.0039, 1.2],
      'pm-acc': [0.0051, 1.11],
    };
    for (const s of ACC_SCHEMES) {
      const e = accErrors(new AccSurface(cage, s), exact, params);
      expect(e.nan).toBe(0);
      expect(Math.abs(e.maxP - expected[s][0]), s).toBeLessThan(0.000055); // the reference values are rounded to 0.01%
      expect(Math.abs(e.maxN - expected[s][1]), s).toBeLessThan(0.0055); // and to 0.01°
    }
  });
});

describe("the tessellator's (triangle, weights) → ACC (face, u, v)", () => {
  it("every prepared triangle maps its corners onto its face's corners", () => {
    const mesh = prepareMesh(creatureCage);
    const S = new AccSurface(creatureCage, 'gregory-acc');
    for (let t = 0; t < mesh.triangleCount; t++) {
      for (let i = 0; i < 3; i++) {
        const w: [number, number, number] = [0, 0, 0];
        w[i] = 1;
        const [f, u, v] = accFaceParam(mesh, creatureCage, t, w);
        const P = S.evaluate(f, u, v).P,
          c = mesh.triVerts[3 * t + i];
        // The corner's limit position: the exact reference's at that vertex.
        expect(dist(P, exactCreature.at(f, u, v).P)).toBeLessThan(1e-12);
        const o = creatureCage.faceOffsets[f],
          m = creatureCage.faceOffsets[f + 1] - o;
        const k = [...Array(m).keys()].find((j) => creatureCage.faceIndices[o + j] === c)!;
        const expected =
          m === 4
            ? [
                [0, 0],
                [1, 0],
                [1, 1],
                [0, 1],
              ][k]
            : [
                [0, 0],
                [1, 0],
                [0, 1],
              ][k];
        close([u, v], expected, 1e-15);
      }
    }
  });
});

describe('what the schemes refuse or ignore', () => {
  it('n-gons are refused with a clear error (accCage refines them first); holes keep their patches; semi-sharp creases are built sharp (σ ≥ 1) or smooth, with a warning', () => {
    expect(() => new AccSurface(loadCage(icosphere).cage, 'gregory-acc')).toThrow(AccError);
    expect(() => new AccSurface(loadCage(icosphere).cage, 'gregory-acc')).toThrow(/5 corners/);
    const holed = loadCage(torus).cage;
    holed.holes.push(3);
    // The hole's patch is built from the same ring points: the patches round it are unchanged.
    const withHole = new AccSurface(holed, 'pm-acc');
    const without = new AccSurface(loadCage(torus).cage, 'pm-acc');
    expect(withHole.points).toEqual(without.points);
    expect(new AccSurface(loadCage(sheet).cage, 'pm-acc').topology.warnings.join()).toMatch(/semi-sharp/);
    const S = new AccSurface(loadCage(creasedBox).cage, 'bezier-acc');
    expect(S.topology.warnings.join()).toMatch(/semi-sharp/);
    // A lone triangle: three boundary corners (edge-and-corner), each interpolated.
    const lone = new AccSurface(makeCage([0, 0, 0, 1, 0, 0, 0, 1, 0], [[0, 1, 2]]), 'bezier-acc');
    close(lone.evaluate(0, 1, 0).P, [1, 0, 0], 1e-15);
  });
});
