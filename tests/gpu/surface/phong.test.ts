/**
 * The Phong surface's CPU reference (src/gpu/surface/phong.ts): its Bézier form against Boubekeur &
 * Alexa's projection formula, the α per edge (the rule, one α per edge, watertight), and the
 * counts its header states.
 */
import { describe, expect, it } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';
import { loadCage } from '../../../src/mesh/index.ts';
import { type PreparedMesh, prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { phongPoint } from '../../../src/gpu/surface/phong.ts';
import { PHONG_MIN_JACOBIAN, phongTriAlphas } from '../../../src/gpu/surface/phong-alpha.ts';
import { PHONG_ALPHA } from '../../../src/gpu/tess/factors.ts';

const MODELS = new URL('../../../public/models/', import.meta.url);
const files = readdirSync(MODELS)
  .filter((f) => f.endsWith('.obj'))
  .sort();
const load = (f: string) => prepareMesh(loadCage(readFileSync(new URL(f, MODELS), 'utf8')).cage);

/** Boubekeur & Alexa 2008 as they write it: the linear point projected onto the corners'
 * tangent planes, the projections interpolated, blended with α. */
function projectionPhong(m: PreparedMesh, t: number, w: number[], alpha: number): number[] {
  const v = [0, 1, 2].map((i) => m.triVerts[3 * t + i]);
  const P = (x: number) => [0, 1, 2].map((c) => m.positions[3 * x + c]);
  const N = (x: number) => [0, 1, 2].map((c) => m.normals[3 * x + c]);
  const p = [0, 1, 2].map((c) => w[0] * P(v[0])[c] + w[1] * P(v[1])[c] + w[2] * P(v[2])[c]);
  const q = [0, 0, 0];
  for (let i = 0; i < 3; i++) {
    const n = N(v[i]);
    const d = [0, 1, 2].reduce((s, c) => s + (p[c] - P(v[i])[c]) * n[c], 0);
    for (let c = 0; c < 3; c++) q[c] += w[i] * (p[c] - d * n[c]);
  }
  return p.map((x, c) => x + alpha * (q[c] - x));
}

function faceCosines(m: PreparedMesh, t: number): number[] {
  const v = [0, 1, 2].map((i) => m.triVerts[3 * t + i]);
  const P = (x: number) => [0, 1, 2].map((c) => m.positions[3 * x + c]);
  const a = P(v[1]).map((x, c) => x - P(v[0])[c]);
  const b = P(v[2]).map((x, c) => x - P(v[0])[c]);
  const f = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const l = Math.hypot(f[0], f[1], f[2]);
  return v.map((x) => (f[0] * m.normals[3 * x] + f[1] * m.normals[3 * x + 1] + f[2] * m.normals[3 * x + 2]) / l);
}

describe('the Phong surface', () => {
  for (const file of files) {
    it(`${file}: the Bézier form at α = 0.75 is the projection formula; every edge has one α, the rule's, and both its triangles meet on it`, () => {
      const m = load(file);
      const uniform = { ...m, triPhongAlpha: new Float32Array(3 * m.triangleCount).fill(PHONG_ALPHA) };
      const scale = m.size;
      let s = 7;
      const rnd = () => (s = (s * 1103515245 + 12345) % 2147483648) / 2147483648;
      let most = 0;
      for (let t = 0; t < m.triangleCount; t++) {
        const a = rnd(),
          b = rnd() * (1 - a);
        const w: [number, number, number] = [1 - a - b, a, b];
        const got = phongPoint(uniform, t, w).pos;
        const want = projectionPhong(m, t, w, PHONG_ALPHA);
        most = Math.max(most, Math.hypot(got[0] - want[0], got[1] - want[1], got[2] - want[2]) / scale);
      }
      expect(most).toBeLessThan(1e-12);

      // One α per edge, from both its triangles; at most PHONG_ALPHA; within every bound its
      // triangles set: (1 − τ)/sin²θ at each corner, 0 where a corner's normal faces away.
      const alphaOf = new Map<number, number>();
      for (let t = 0; t < m.triangleCount; t++) {
        const cos = faceCosines(m, t);
        const bound = Math.min(PHONG_ALPHA, ...cos.map((c) => (c <= 0 ? 0 : (1 - PHONG_MIN_JACOBIAN) / (1 - Math.min(1, c * c)))));
        for (let i = 0; i < 3; i++) {
          const e = m.triEdges[3 * t + i];
          const alpha = m.triPhongAlpha[3 * t + i];
          if (alphaOf.has(e)) expect(alpha).toBe(alphaOf.get(e));
          alphaOf.set(e, alpha);
          expect(alpha).toBeLessThanOrEqual(Math.fround(bound) + 1e-7);
          expect(alpha).toBeGreaterThanOrEqual(0);
        }
      }
      // And no lower than the least bound of its triangles (it is that least bound).
      const least = new Float64Array(m.edgeCount).fill(PHONG_ALPHA);
      for (let t = 0; t < m.triangleCount; t++) {
        const cos = faceCosines(m, t);
        const bound = Math.min(PHONG_ALPHA, ...cos.map((c) => (c <= 0 ? 0 : (1 - PHONG_MIN_JACOBIAN) / (1 - Math.min(1, c * c)))));
        for (let i = 0; i < 3; i++) least[m.triEdges[3 * t + i]] = Math.min(least[m.triEdges[3 * t + i]], bound);
      }
      for (const [e, alpha] of alphaOf) expect(alpha).toBeCloseTo(least[e], 6);

      // Watertight: a point of an edge is the same from both its triangles.
      const owners = new Map<number, [number, number][]>();
      for (let t = 0; t < m.triangleCount; t++)
        for (let i = 0; i < 3; i++) {
          const e = m.triEdges[3 * t + i];
          if (!owners.has(e)) owners.set(e, []);
          owners.get(e)?.push([t, i]);
        }
      let gap = 0;
      for (const sides of owners.values()) {
        if (sides.length !== 2) continue;
        for (const u of [0.1, 0.37, 0.5, 0.8]) {
          const at = ([t, i]: [number, number], from: number) => {
            const w: [number, number, number] = [0, 0, 0];
            w[i] = 1 - u;
            w[(i + 1) % 3] = u;
            // The same point: measured from the edge's lower vertex.
            if (m.triVerts[3 * t + i] !== from) {
              w[i] = u;
              w[(i + 1) % 3] = 1 - u;
            }
            return phongPoint(m, t, w).pos;
          };
          const lo = Math.min(m.triVerts[3 * sides[0][0] + sides[0][1]], m.triVerts[3 * sides[0][0] + ((sides[0][1] + 1) % 3)]);
          const p = at(sides[0], lo),
            q = at(sides[1], lo);
          gap = Math.max(gap, Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) / scale);
        }
      }
      expect(gap).toBeLessThan(1e-12);
    });
  }

  it("lowers α only where a corner's normal tilts far from its face: the counts src/gpu/surface/phong.ts states", () => {
    const lowered = (f: string) => {
      const m = load(f);
      const alpha = new Float64Array(m.edgeCount).fill(PHONG_ALPHA);
      for (let k = 0; k < m.triEdges.length; k++) alpha[m.triEdges[k]] = m.triPhongAlpha[k];
      const low = [...alpha].filter((a) => a < PHONG_ALPHA);
      return { edges: m.edgeCount, lowered: low.length, zero: low.filter((a) => a === 0).length, least: Math.min(PHONG_ALPHA, ...low) };
    };
    expect(lowered('creature.obj')).toMatchObject({ edges: 1692, lowered: 411, zero: 56 });
    expect(lowered('creased-box.obj')).toMatchObject({ edges: 72, lowered: 56 });
    expect(lowered('creased-box.obj').least).toBeCloseTo(0.645, 3);
    expect(lowered('gear.obj')).toMatchObject({ edges: 450, lowered: 260 });
    expect(lowered('gear.obj').least).toBeCloseTo(0.573, 3);
    expect(lowered('pawn.obj')).toMatchObject({ edges: 720, lowered: 128 });
    expect(lowered('pawn.obj').least).toBeCloseTo(0.551, 3);
    for (const f of ['icosphere.obj', 'torus.obj', 'sheet.obj']) expect(lowered(f).lowered).toBe(0);
  });

  it('phongTriAlphas follows moved normals (an animated cage): a normal turned into a face plane lowers its edges', () => {
    const m = load('icosphere.obj');
    expect(m.triPhongAlpha.every((a) => a === PHONG_ALPHA)).toBe(true);
    const normals = Float32Array.from(m.normals);
    // Turn vertex 0's normal to lie in the plane of one of its faces: along that face's edge.
    const t = [...Array(m.triangleCount).keys()].find((k) => m.triVerts[3 * k] === 0) ?? 0;
    const a = m.triVerts[3 * t + 1];
    const d = [0, 1, 2].map((c) => m.positions[3 * a + c] - m.positions[c]);
    const l = Math.hypot(d[0], d[1], d[2]);
    for (let c = 0; c < 3; c++) normals[c] = d[c] / l;
    const moved = phongTriAlphas(m, m.positions, normals);
    expect(moved[3 * t]).toBeCloseTo(Math.fround(1 - PHONG_MIN_JACOBIAN), 6);
    expect([...moved].filter((x) => x < PHONG_ALPHA).length).toBeGreaterThan(0);
  });
});
