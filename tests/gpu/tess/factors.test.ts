import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';
import { ONE } from '../../../src/pattern/fixed.ts';
import fc from 'fast-check';
import { mat4 } from 'gl-matrix';
import {
  BULGE_ALPHA,
  BULGE_OFF_SCREEN,
  BULGE_WEIGHTS,
  bulgeFactor,
  edgeFactor,
  phongMidpointOffset,
  budgetCandidate,
  outputCapacity,
  sphereOutsideFrustum,
  type FactorRule,
  type Vec3,
} from '../../../src/gpu/tess/factors.ts';
import { faceParam, inverseBilinear } from '../../../src/gpu/tess/face-params.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { makeCage } from '../../../src/mesh/types.ts';
import { grid2d } from '../../../src/gpu/tess/tessellator.ts';
import { BUDGET_SCALES } from '../../../src/gpu/contract/tess.ts';

const view = mat4.lookAt(mat4.create(), [0, 0, 5], [0, 0, 0], [0, 1, 0]);
const proj = mat4.perspectiveZO(mat4.create(), Math.PI / 4, 1, 0.1, 100);
const rule = (over: Partial<FactorRule> = {}): FactorRule => ({
  mode: 'adaptive',
  fixedFactor: 1,
  lodScale: 1,
  viewProj: mat4.multiply(mat4.create(), proj, view),
  eye: [0, 0, 5],
  pixelAngle: Math.PI / 4 / 1080,
  maxFactor: 64,
  ...over,
});
const unit = (v: number[]): Vec3 => {
  const l = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / l, v[1] / l, v[2] / l];
};
// An arc of the unit circle seen from the eye: normals are the radial directions.
const arc = (theta: number): [Vec3, Vec3, Vec3, Vec3] => [
  [Math.sin(-theta / 2), 0, Math.cos(-theta / 2)],
  [Math.sin(theta / 2), 0, Math.cos(theta / 2)],
  unit([Math.sin(-theta / 2), 0, Math.cos(-theta / 2)]),
  unit([Math.sin(theta / 2), 0, Math.cos(theta / 2)]),
];

describe('edge factor rule', () => {
  it('is symmetric in the two ends of the edge', () => {
    const v = fc.tuple(
      fc.double({ min: -2, max: 2, noNaN: true }),
      fc.double({ min: -2, max: 2, noNaN: true }),
      fc.double({ min: -2, max: 2, noNaN: true }),
    );
    fc.assert(
      fc.property(v, v, v, v, (p0, p1, a, b) => {
        if (Math.hypot(...a) < 1e-3 || Math.hypot(...b) < 1e-3) return;
        const n0 = unit(a),
          n1 = unit(b);
        expect(edgeFactor(p0, p1, n0, n1, rule())).toBeCloseTo(edgeFactor(p1, p0, n1, n0, rule()), 9);
        const e = phongMidpointOffset(p0, p1, n0, n1),
          f = phongMidpointOffset(p1, p0, n1, n0);
        for (let i = 0; i < 3; i++) expect(e[i]).toBeCloseTo(f[i], 12);
      }),
      { numRuns: 500 },
    );
  });

  it('is 1 on flat geometry and grows with curvature, LOD scale and closeness', () => {
    expect(edgeFactor([-1, 0, 0], [1, 0, 0], [0, 0, 1], [0, 0, 1], rule())).toBe(1);
    const [p0, p1, n0, n1] = arc(0.5);
    const base = edgeFactor(p0, p1, n0, n1, rule());
    expect(base).toBeGreaterThan(1);
    const [q0, q1, m0, m1] = arc(1.0);
    expect(edgeFactor(q0, q1, m0, m1, rule())).toBeGreaterThan(base);
    expect(edgeFactor(p0, p1, n0, n1, rule({ lodScale: 4 }))).toBeCloseTo(Math.min(64, 2 * base), 6);
    expect(edgeFactor(p0, p1, n0, n1, rule({ eye: [0, 0, 3] }))).toBeGreaterThan(base);
  });

  it('follows k = sqrt(lod·|e| / (dist·pixelAngle)), clamped to [1, max]', () => {
    const [p0, p1, n0, n1] = arc(0.3);
    const e = phongMidpointOffset(p0, p1, n0, n1);
    const el = Math.hypot(...e);
    const mid = [0, 1, 2].map((i) => (p0[i] + p1[i]) / 2 + e[i]);
    const dist = Math.hypot(mid[0], mid[1], mid[2] - 5);
    const r = rule();
    expect(edgeFactor(p0, p1, n0, n1, r)).toBeCloseTo(Math.sqrt(el / (dist * r.pixelAngle)), 9);
    expect(edgeFactor(p0, p1, n0, n1, rule({ lodScale: 1e6 }))).toBe(64);
  });

  it('counts twice the offset across the line of sight on an edge whose two ends face the eye', () => {
    const [p0, p1, n0, n1] = arc(0.6);
    const e = phongMidpointOffset(p0, p1, n0, n1);
    const el = Math.hypot(...e);
    const mid = [0, 1, 2].map((i) => (p0[i] + p1[i]) / 2 + e[i]);
    const expected = (eye: Vec3, seen: number) =>
      Math.sqrt(seen / (Math.hypot(mid[0] - eye[0], mid[1] - eye[1], mid[2] - eye[2]) * rule().pixelAngle));
    const across = (eye: Vec3) => {
      const d = Math.hypot(mid[0] - eye[0], mid[1] - eye[1], mid[2] - eye[2]);
      const r = [0, 1, 2].map((i) => (mid[i] - eye[i]) / d);
      const along = e[0] * r[0] + e[1] * r[1] + e[2] * r[2];
      return Math.hypot(e[0] - along * r[0], e[1] - along * r[1], e[2] - along * r[2]);
    };
    // Seen obliquely (both ends facing, the offset ~37° off the ray): 2|e⊥| ≈ 1.2|e| wins.
    const oblique: Vec3 = [3, 0, 4];
    expect(2 * across(oblique)).toBeGreaterThan(1.1 * el);
    expect(edgeFactor(p0, p1, n0, n1, rule({ eye: oblique }))).toBeCloseTo(expected(oblique, 2 * across(oblique)), 9);
    // Head-on the offset lies along the ray: |e| alone.
    expect(edgeFactor(p0, p1, n0, n1, rule())).toBeCloseTo(expected([0, 0, 5], el), 9);
    // Grazing (one end turned away): |e| alone, however much of it lies across the ray.
    const grazing: Vec3 = [5, 0, 0.3];
    expect(2 * across(grazing)).toBeGreaterThan(1.5 * el);
    expect(edgeFactor(p0, p1, n0, n1, rule({ eye: grazing }))).toBeCloseTo(expected(grazing, el), 9);
  });

  it('drops off-screen and back-facing edges to 1, and never returns NaN or less than 1', () => {
    const [p0, p1, n0, n1] = arc(0.8);
    const behind = (p: Vec3): Vec3 => [p[0], p[1] + 50, p[2]];
    expect(edgeFactor(behind(p0), behind(p1), n0, n1, rule())).toBe(1);
    const flip = (n: Vec3): Vec3 => [-n[0], -n[1], -n[2]];
    expect(edgeFactor(p0, p1, flip(n0), flip(n1), rule())).toBe(1);
    expect(edgeFactor([NaN, 0, 0], [1, 0, 0], n0, n1, rule())).toBe(1);
    expect(edgeFactor(p0, p1, n0, n1, rule({ mode: 'fixed', fixedFactor: NaN }))).toBe(1);
    expect(edgeFactor(p0, p1, n0, n1, rule({ mode: 'fixed', fixedFactor: -3 }))).toBe(1);
    expect(edgeFactor(p0, p1, n0, n1, rule({ mode: 'fixed', fixedFactor: 500 }))).toBe(64);
  });

  it('culls spheres outside the frustum and keeps those inside', () => {
    const m = mat4.multiply(mat4.create(), proj, view);
    expect(sphereOutsideFrustum(m, [0, 0, 0], 0.1)).toBe(false);
    expect(sphereOutsideFrustum(m, [0, 0, 10], 0.1)).toBe(true); // behind the eye
    expect(sphereOutsideFrustum(m, [40, 0, 0], 1)).toBe(true);
    expect(sphereOutsideFrustum(m, [3, 0, 0], 2)).toBe(false); // straddles the side plane
  });
});

describe('bulge term', () => {
  // A triangle facing the eye at z = 0, 5 away; the surface over it bulges towards the eye by
  // h·(a bump that is 0 on the edges), its normal +z.
  const corners: [Vec3, Vec3, Vec3] = [
    [-1, -1, 0],
    [1, -1, 0],
    [0, 1, 0],
  ];
  const bump =
    (h: number, normal: Vec3 = [0, 0, 1]) =>
    (w: Vec3) => {
      const b = [w[0] / ONE, w[1] / ONE, w[2] / ONE];
      const pos = [0, 1, 2].map((c) => b[0] * corners[0][c] + b[1] * corners[1][c] + b[2] * corners[2][c]);
      pos[2] += 27 * h * b[0] * b[1] * b[2];
      return { pos, normal };
    };

  it('samples the centroid and the three points (2/3, 1/6, 1/6), in 16.16 as the WGSL makes them', () => {
    expect(BULGE_WEIGHTS).toHaveLength(4);
    for (const w of BULGE_WEIGHTS) expect(w[0] + w[1] + w[2]).toBe(ONE);
    expect(BULGE_WEIGHTS[3]).toEqual([21845, 21845, 21846]);
    expect(BULGE_WEIGHTS[1]).toEqual([10922, 43692, 10922]);
  });

  it('has the constants of wgsl/tess/factor-bulge.wgsl', () => {
    const wgsl = readFileSync(new URL('../../../wgsl/tess/factor-bulge.wgsl', import.meta.url), 'utf8');
    const constant = (name: string) => Number(new RegExp(`const ${name}: \\w+ = ([-0-9.]+)`).exec(wgsl)?.[1]);
    expect(constant('BULGE_ALPHA')).toBe(BULGE_ALPHA);
    expect(constant('BULGE_OFF_SCREEN')).toBe(BULGE_OFF_SCREEN);
    expect(constant('BULGE_SAMPLES')).toBe(BULGE_WEIGHTS.length);
  });

  it('is 0 on a flat triangle and follows k = sqrt(α·lod·bulge / (dist·pixelAngle)) at the largest sample', () => {
    const r = rule();
    expect(bulgeFactor(corners, bump(0), r)).toBe(0);
    // The centroid bulges most (by h; the other samples by h/2), and is the nearest to the eye.
    for (const h of [1e-3, 1e-2, 0.1]) {
      const k = bulgeFactor(corners, bump(h), r);
      const centroid = bump(h)(BULGE_WEIGHTS[3]).pos;
      const c = BULGE_WEIGHTS[3].map((x) => x / ONE);
      const b = 27 * h * c[0] * c[1] * c[2];
      const dist = Math.hypot(centroid[0], centroid[1], centroid[2] - 5);
      expect(k).toBeCloseTo(Math.sqrt((BULGE_ALPHA * b) / (dist * r.pixelAngle)), 9);
      expect(bulgeFactor(corners, bump(h), rule({ lodScale: 4 }))).toBeCloseTo(2 * k, 9);
    }
  });

  it('is BULGE_OFF_SCREEN off screen, and does not drop for a triangle facing away', () => {
    const r = rule();
    const k = bulgeFactor(corners, bump(0.1), r);
    expect(k).toBeGreaterThan(1);
    expect(bulgeFactor(corners, bump(0.1, [0, 0, -1]), r)).toBe(k);
    // Behind the eye (the eye at z = 5 looks down −z), and far to the side.
    const moved = (d: Vec3) => corners.map((p) => [p[0] + d[0], p[1] + d[1], p[2] + d[2]]) as unknown as [Vec3, Vec3, Vec3];
    for (const d of [
      [0, 0, 10],
      [50, 0, 0],
    ] as Vec3[]) {
      const c = moved(d);
      const surface = (w: Vec3) => ({ pos: bump(0.1)(w).pos.map((x, i) => x + d[i]) });
      expect(bulgeFactor(c, surface, r)).toBe(BULGE_OFF_SCREEN);
    }
  });

  it("raises an edge to its triangles' bulge term, and keeps an edge whose ends face away when a triangle is on screen", () => {
    const r = rule();
    const p0: Vec3 = [-1, 0, 0],
      p1: Vec3 = [1, 0, 0];
    const n: Vec3 = [0, 0, 1];
    expect(edgeFactor(p0, p1, n, n, r)).toBe(1);
    expect(edgeFactor(p0, p1, n, n, r, 7.5)).toBe(7.5);
    expect(edgeFactor(p0, p1, n, n, r, BULGE_OFF_SCREEN)).toBe(1);
    const away: Vec3 = [0, 0, -1];
    expect(edgeFactor(p0, p1, away, away, r, BULGE_OFF_SCREEN)).toBe(1);
    expect(edgeFactor(p0, p1, away, away, r, 7.5)).toBe(7.5);
    expect(edgeFactor(p0, p1, n, n, r, 100)).toBe(64);
  });
});

describe('budget and buffer sizing', () => {
  it('takes the largest candidate scale that fits; the candidates halve the counts down to factor 1', () => {
    expect(BUDGET_SCALES[0]).toBe(1);
    expect(BUDGET_SCALES.at(-1)).toBe(0); // factor 1 everywhere
    for (let c = 1; c + 1 < BUDGET_SCALES.length; c++) expect(BUDGET_SCALES[c] ** 2).toBeCloseTo(BUDGET_SCALES[c - 1] ** 2 / 2, 12);
    const totals = (v: number[]) => v.map((n) => ({ vertices: n, triangles: n }));
    expect(budgetCandidate(totals([100, 50, 25]), 100, 100)).toEqual({ candidate: 0, fits: true });
    expect(budgetCandidate(totals([400, 200, 100, 50]), 150, 1000)).toEqual({ candidate: 2, fits: true });
    expect(budgetCandidate(totals([400, 200]), 10, 10)).toEqual({ candidate: 1, fits: false });
  });
  it('sizes the outputs from the device limits, never above what one binding holds', () => {
    expect(outputCapacity({ maxStorageBufferBindingSize: 128 << 20, maxBufferSize: 256 << 20 })).toEqual({
      vertexCapacity: Math.floor((128 << 20) / 12),
      triangleCapacity: Math.floor((128 << 20) / 12),
    });
    expect(outputCapacity({ maxStorageBufferBindingSize: 2 ** 31, maxBufferSize: 2 ** 32 })).toEqual({
      vertexCapacity: 1 << 24,
      triangleCapacity: 1 << 24,
    });
    expect(outputCapacity({ maxStorageBufferBindingSize: 2 ** 31, maxBufferSize: 2 ** 32 }, { vertexCapacity: 1000 }).vertexCapacity).toBe(
      1000,
    );
  });
  it('folds dispatches wider than 65535 workgroups into 2D', () => {
    expect(grid2d(10)).toEqual([10, 1]);
    expect(grid2d(65535)).toEqual([65535, 1]);
    expect(grid2d(65536)).toEqual([65535, 2]);
    const [x, y] = grid2d(1 << 20);
    expect(x * y).toBeGreaterThanOrEqual(1 << 20);
    expect(x).toBeLessThanOrEqual(65535);
  });
});

describe('face parameters for --params', () => {
  it('maps the two triangles of a quad linearly', () => {
    const cage = makeCage([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], [[0, 1, 2, 3]]);
    const mesh = prepareMesh(cage);
    expect(faceParam(mesh, cage, 0, [1 / 3, 1 / 3, 1 / 3])).toEqual({ face: 0, u: 2 / 3, v: 1 / 3 });
    expect(faceParam(mesh, cage, 1, [0, 0.5, 0.5])).toEqual({ face: 0, u: 0.5, v: 1 });
  });
  it('on a triangle face equals the closed form (k = argmax, s = 2·w_{k+1} on edge k→k+1)', () => {
    const cage = makeCage([0, 0, 0, 1, 0, 0, 0, 1, 0], [[0, 1, 2]]);
    const mesh = prepareMesh(cage);
    fc.assert(
      fc.property(fc.double({ min: 0, max: 1, noNaN: true }), fc.double({ min: 0, max: 1, noNaN: true }), (a, b) => {
        const w = [a, b * (1 - a), (1 - a) * (1 - b)] as [number, number, number];
        const k = w.indexOf(Math.max(...w));
        const p = faceParam(mesh, cage, 0, w) as { k: number; s: number; t: number };
        if (w.filter((x) => x === w[k]).length > 1) return; // on a sub-face boundary either side is right
        expect(p.k).toBe(k);
        const bn = w[(k + 1) % 3],
          bp = w[(k + 2) % 3],
          d = bn - bp;
        const s = (12 * bn) / (3 + 2 * d + Math.sqrt(Math.max(0, (3 + 2 * d) ** 2 - 24 * bn)));
        const t = (12 * bp) / (3 - 2 * d + Math.sqrt(Math.max(0, (3 - 2 * d) ** 2 - 24 * bp)));
        expect(p.s).toBeCloseTo(s, 9);
        expect(p.t).toBeCloseTo(t, 9);
      }),
      { numRuns: 500 },
    );
  });
  it('fans a face of five or more corners round a centre vertex: its corner 0 maps to the face centre, the spokes to the kite edges', () => {
    // A non-planar hexagon with one hole face beside it: the centre is the corners' mean with
    // the face's (Newell) normal, after the cage's vertices; triangle k is (centre, k, k + 1).
    const n = 6;
    const pos: number[] = [];
    for (let k = 0; k < n; k++) pos.push(Math.cos((2 * Math.PI * k) / n) * (1 + 0.1 * k), Math.sin((2 * Math.PI * k) / n), 0.05 * (k % 2));
    const cage = makeCage(pos, [[0, 1, 2, 3, 4, 5]]);
    const mesh = prepareMesh(cage);
    expect([mesh.cageVertexCount, mesh.vertexCount, mesh.triangleCount, mesh.edgeCount]).toEqual([6, 7, 6, 12]);
    expect(Array.from(mesh.triFan)).toEqual([0, 1, 2, 3, 4, 5]);
    for (let k = 0; k < n; k++) expect(Array.from(mesh.triVerts.subarray(3 * k, 3 * k + 3))).toEqual([6, k, (k + 1) % n]);
    for (let c = 0; c < 3; c++) {
      let mean = 0;
      for (let k = 0; k < n; k++) mean += pos[3 * k + c] / n;
      expect(mesh.positions[18 + c]).toBeCloseTo(mean, 6);
    }
    expect(mesh.normals[20]).toBeGreaterThan(0.99); // the face's normal, nearly +z
    // The parameter: the centre is (1, 1) of a sub-face; corner k is (0, 0) of sub-face k; the
    // spoke's midpoint lies on the kite edge from the centre towards corner k, at s = 0.
    const centre = faceParam(mesh, cage, 2, [1, 0, 0]) as { k: number; s: number; t: number };
    expect([centre.s, centre.t]).toEqual([1, 1]);
    const corner = faceParam(mesh, cage, 2, [0, 1, 0]) as { k: number; s: number; t: number };
    expect(corner.k).toBe(2);
    expect(Math.abs(corner.s) + Math.abs(corner.t)).toBeLessThan(1e-12);
    const spoke = faceParam(mesh, cage, 2, [0.5, 0.5, 0]) as { k: number; s: number; t: number };
    expect(spoke.k).toBe(2);
    expect(spoke.s).toBeCloseTo(spoke.t, 9);
    // Points of one triangle never leave its two kites (k and k + 1).
    fc.assert(
      fc.property(fc.double({ min: 0, max: 1, noNaN: true }), fc.double({ min: 0, max: 1, noNaN: true }), (a, b) => {
        const w = [a, b * (1 - a), (1 - a) * (1 - b)] as [number, number, number];
        if (w[0] > 1 - 1e-9) return; // at the centre every sub-face is right
        const p = faceParam(mesh, cage, 2, w) as { k: number; s: number; t: number };
        expect([2, 3]).toContain(p.k);
      }),
      { numRuns: 300 },
    );
  });
  it('inverts a bilinear map', () => {
    const a = [0, 0],
      b = [2, 0.2],
      c = [1.5, 1.7],
      d = [-0.2, 1];
    const [s, t] = inverseBilinear([0.9, 0.6], a, b, c, d);
    const x = (1 - s) * (1 - t) * a[0] + s * (1 - t) * b[0] + s * t * c[0] + (1 - s) * t * d[0];
    expect(x).toBeCloseTo(0.9, 12);
  });
});
