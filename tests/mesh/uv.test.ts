// Face-varying UVs through the mesh layer: OBJ vt / f v/vt/vn in and out, coverage, seams,
// and "linear all" interpolation over quads and n-gon sub-faces (src/mesh/uv.ts).
import { describe, expect, it } from 'vitest';
import {
  CageError,
  buildTopology,
  loadCage,
  makeCage,
  uvTexelCoverage,
  parseObj,
  uvAt,
  uvAtSubFace,
  uvCoverage,
  uvSeams,
  writeObj,
  requireUvs,
} from '../../src/mesh/index.ts';

// Three quads on a sheet: quads A (0) and B (1) are separate uv islands (edge 2-5, 1-based, is a
// seam); quad C (2) shares its edge 4-5 with A continuously (same vt on both sides).
const STRIP = `v 0 0 0
v 1 0 0
v 2 0 0
v 0 1 0
v 1 1 0
v 2 1 0
v 0.5 1.8 0
v 1.2 1.7 0
vt 0 0
vt 0.5 0
vt 0.5 0.5
vt 0 0.5
vt 0.6 0
vt 1 0
vt 1 0.5
vt 0.6 0.5
vt 0.1 0.9
vt 0.45 0.85
vn 0 0 1
f 1/1/1 2/2/1 5/3/1 4/4/1
f 2/5/1 3/6/1 6/7/1 5/8/1
f 4/4/1 5/3/1 8/10/1 7/9/1
`;

describe('face-varying UVs in the mesh layer', () => {
  it('reads vt and per-corner vt indices, and writeObj round-trips them', () => {
    const text = STRIP + 'v 1.5 1.5 0\n';
    const { cage } = loadCage(text);
    expect(cage.uvs.length).toBe(20);
    expect(Array.from(cage.faceUvIndices)).toEqual([0, 1, 2, 3, 4, 5, 6, 7, 3, 2, 9, 8]);
    expect(uvCoverage(cage)).toBe('complete');
    const again = parseObj(writeObj(cage)).cage;
    expect(Array.from(again.uvs)).toEqual(Array.from(cage.uvs));
    expect(Array.from(again.faceUvIndices)).toEqual(Array.from(cage.faceUvIndices));
    expect(Array.from(again.faceNormalIndices)).toEqual(Array.from(cage.faceNormalIndices));
    expect(writeObj(again)).toBe(writeObj(cage));
  });

  it('partial UVs load with a warning naming the face line, and are refused for interpolation', () => {
    const text = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nvt 0 0\nf 1/1 2/1 3/1 4/1\nf 2 5 3\n';
    const { cage, warnings } = loadCage(text);
    expect(uvCoverage(cage)).toBe('partial');
    expect(warnings.find((w) => w.line === 8 && /texture coordinates/.test(w.message))).toBeDefined();
    expect(() => requireUvs(cage)).toThrow(CageError);
    try {
      requireUvs(cage);
    } catch (e) {
      expect((e as CageError).issues[0].line).toBe(8);
    }
    expect(uvCoverage(loadCage('v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n').cage)).toBe('none');
  });

  it('a vt index out of range names the face line', () => {
    expect(() => loadCage('v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nf 1/1 2/2 3/1\n')).toThrow(/line 5|texture coordinate index 2/);
    try {
      loadCage('v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nf 1/1 2/2 3/1\n');
    } catch (e) {
      expect((e as CageError).issues.some((i) => i.line === 5 && /texture coordinate index 2 is out of range/.test(i.message))).toBe(true);
    }
  });

  const pent = (): ReturnType<typeof loadCage>['cage'] =>
    loadCage(
      'v 0 0 0\nv 1 0 0\nv 1.3 0.9 0\nv 0.5 1.5 0\nv -0.3 0.9 0\n' +
        'vt 0.1 0.2\nvt 0.9 0.1\nvt 1 0.8\nvt 0.5 1\nvt 0 0.7\nf 1/1 2/2 3/3 4/4 5/5\n',
    ).cage;

  it('quads are bilinear in (u,v); n-gon sub-faces are bilinear over corner, midpoints and centre', () => {
    const { cage } = loadCage(STRIP);
    expect(uvAt(cage, 0, 0, 0).uv).toEqual([0, 0]);
    expect(uvAt(cage, 0, 1, 1).uv).toEqual([0.5, 0.5]);
    expect(uvAt(cage, 1, 0, 1).uv).toEqual([0.6, 0.5]);
    const q = uvAt(cage, 1, 0.25, 0.5);
    expect(q.uv[0]).toBeCloseTo(0.7, 15);
    expect(q.uv[1]).toBeCloseTo(0.25, 15);
    expect(q.dUvdu[0]).toBeCloseTo(0.4, 15);
    expect(q.dUvdv[1]).toBeCloseTo(0.5, 15);
    const c = pent();
    const cen = [0, 0];
    for (let j = 0; j < 5; j++) {
      cen[0] += c.uvs[2 * j] / 5;
      cen[1] += c.uvs[2 * j + 1] / 5;
    }
    for (let k = 0; k < 5; k++) {
      expect(uvAtSubFace(c, 0, k, 0, 0).uv).toEqual([c.uvs[2 * k], c.uvs[2 * k + 1]]);
      const m = uvAtSubFace(c, 0, k, 1, 1).uv;
      expect(m[0]).toBeCloseTo(cen[0], 15);
      expect(m[1]).toBeCloseTo(cen[1], 15);
      // The midpoint of edge k → k+1 is reached from both sub-faces that share it.
      const a = uvAtSubFace(c, 0, k, 1, 0).uv,
        b = uvAtSubFace(c, 0, (k + 1) % 5, 0, 1).uv;
      expect(a[0]).toBeCloseTo(b[0], 15);
      expect(a[1]).toBeCloseTo(b[1], 15);
    }
    // Derivatives match central differences of the interpolant.
    const d = 1e-6,
      p = uvAtSubFace(c, 0, 2, 0.3, 0.6);
    const fu = [uvAtSubFace(c, 0, 2, 0.3 + d, 0.6).uv, uvAtSubFace(c, 0, 2, 0.3 - d, 0.6).uv];
    const fv = [uvAtSubFace(c, 0, 2, 0.3, 0.6 + d).uv, uvAtSubFace(c, 0, 2, 0.3, 0.6 - d).uv];
    for (let i = 0; i < 2; i++) {
      expect(Math.abs((fu[0][i] - fu[1][i]) / (2 * d) - p.dUvdu[i])).toBeLessThan(1e-9);
      expect(Math.abs((fv[0][i] - fv[1][i]) / (2 * d) - p.dUvdv[i])).toBeLessThan(1e-9);
    }
    expect(() => uvAt(c, 0, 0.5, 0.5)).toThrow(/5 corners/);
    expect(() => uvAtSubFace(c, 0, 5, 0.5, 0.5)).toThrow(/sub-face 5/);
    expect(() => uvAtSubFace(c, 0, 0, 1.5, 0.5)).toThrow(/outside/);
  });

  it('finds UV seams by value: the islands edge is a seam, the shared edge is not', () => {
    const { cage, topology } = loadCage(STRIP);
    const s = uvSeams(cage, topology);
    const edge = (a: number, b: number): number => {
      for (let e = 0; e < topology.nEdges; e++) {
        const p = topology.edgeVerts[2 * e],
          q = topology.edgeVerts[2 * e + 1];
        if ((p === a && q === b) || (p === b && q === a)) return e;
      }
      return -1;
    };
    expect(s.edge[edge(1, 4)]).toBe(1); // quads A and B: separate islands
    expect(s.edge[edge(3, 4)]).toBe(0); // quad A and quad C share vt 4 and 3 on it
    expect(Array.from(s.edge).reduce((a, b) => a + b, 0)).toBe(1);
    expect(s.vertex[1]).toBe(1);
    expect(s.vertex[4]).toBe(1);
    expect(s.vertex[3]).toBe(0);
    expect(s.vertex[0]).toBe(0);
    // Distinct vt lines with equal values are not a seam.
    const dup = loadCage('v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 1 1\nf 1/1 2/2 3/3\nf 1/1 3/5 4/4\n');
    expect(Array.from(uvSeams(dup.cage, buildTopology(dup.cage)).edge).every((x) => x === 0)).toBe(true);
  });

  it('counts the texels whose centres the uv polygons cover, folding or dropping the outside', () => {
    const quad = (u0: number, u1: number, v0: number, v1: number) => ({
      ...makeCage([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], [[0, 1, 2, 3]]),
      uvs: Float64Array.from([u0, v0, u1, v0, u1, v1, u0, v1]),
      faceUvIndices: Int32Array.from([0, 1, 2, 3]),
    });
    // A quarter of an 8 x 8 map: 4 x 4 texel centres, in the bottom-left (image rows 4..7, columns 0..3).
    const a = uvTexelCoverage(quad(0, 0.5, 0, 0.5), 8, 8);
    expect(a.covered).toBe(16);
    expect(a.mask[7 * 8 + 0]).toBe(1);
    expect(a.mask[3 * 8 + 0]).toBe(0);
    expect(a.mask[7 * 8 + 4]).toBe(0);
    // Straddling u = 1: repeat folds the outside half back to columns 0..1, clamp drops it.
    const r = uvTexelCoverage(quad(0.75, 1.25, 0, 0.5), 8, 8, 'repeat');
    expect(r.covered).toBe(16);
    expect(r.mask[7 * 8 + 1]).toBe(1);
    expect(uvTexelCoverage(quad(0.75, 1.25, 0, 0.5), 8, 8, 'clamp').covered).toBe(8);
    // Two faces on the same uvs count each texel once.
    const twin = {
      ...makeCage(
        [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, 0, 2, 1, 0],
        [
          [0, 1, 2, 3],
          [1, 4, 5, 2],
        ],
      ),
      uvs: Float64Array.from([0, 0, 0.5, 0, 0.5, 0.5, 0, 0.5]),
      faceUvIndices: Int32Array.from([0, 1, 2, 3, 0, 1, 2, 3]),
    };
    expect(uvTexelCoverage(twin, 8, 8).covered).toBe(16);
    // A triangle: the centres below its diagonal, and (crossing rule) those on it.
    const t = loadCage('v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\n').cage;
    expect(uvTexelCoverage(t, 16, 16).covered).toBe(120 + 16);
  });
});
