import { describe, it, expect } from 'vitest';
import fc from 'fast-check';
import { mat4 } from 'gl-matrix';
import {
  edgeFactor,
  phongMidpointOffset,
  budgetScale,
  outputCapacity,
  sphereOutsideFrustum,
  type FactorRule,
  type Vec3,
} from '../src/gpu/factors.ts';
import { faceParam, inverseBilinear } from '../src/gpu/face-params.ts';
import { prepareMesh } from '../src/gpu/prepare.ts';
import { makeCage } from '../src/mesh/types.ts';
import { grid2d } from '../src/gpu/tessellator.ts';

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

describe('budget and buffer sizing', () => {
  it('keeps the scale at 1 when everything fits, else shrinks it so that f² scaling fits', () => {
    expect(budgetScale(100, 100, 100, 100)).toBe(1);
    const s = budgetScale(4000, 1000, 1000, 1000);
    expect(s).toBeLessThan(0.5);
    expect(4000 * s * s).toBeLessThan(1000);
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
  it("on a triangle face equals the notes' closed form (k = argmax, s = 2·w_{k+1} on edge k→k+1)", () => {
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
