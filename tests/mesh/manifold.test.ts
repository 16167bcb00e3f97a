// Non-manifold cages split apart as OpenSubdiv makes them sharp (src/mesh/manifold.ts). The limit
// surfaces are held equal to OpenSubdiv's by the CI's cross-check (tools/osd-check: its nine
// non-manifold regression cages and tools/osd-check/cages/nonmanifold_fin.obj, 4e-16 of the
// diagonal); here, the split itself: fans become vertices, tags follow every copy, the vertices
// OpenSubdiv sharpens get corners, and a crease copy with one face is not sharpened as a corner.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import {
  SHARPNESS_INFINITE,
  buildTopology,
  computeSharpness,
  formatIssue,
  loadCage,
  makeCage,
  parseObj,
  splitNonManifold,
} from '../../src/mesh/index.ts';

const FIN = readFileSync(new URL('../../tools/osd-check/cages/nonmanifold_fin.obj', import.meta.url), 'utf8');

describe('splitNonManifold', () => {
  it('a manifold cage is returned as it is', () => {
    const cage = makeCage([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], [[0, 1, 2, 3]]);
    const r = splitNonManifold(cage);
    expect(r.cage).toBe(cage);
    expect(r.warnings).toEqual([]);
  });

  it('a fin along a line: one copy per fan, the line a crease (no corner), its one-face copy exempt from corner sharpening', () => {
    const { cage, warnings, vertexOrigin } = splitNonManifold(parseObj(FIN).cage);
    // Vertex 2 (the crease) and 1 (the line's end on the sheet's boundary): 3 fans each; 3 (the
    // line's end inside the sheet): 2 (the sheet, the fin).
    expect(cage.positions.length / 3).toBe(12 + 2 + 2 + 1);
    expect(warnings.map(formatIssue).join('\n')).toMatch(
      /non-manifold vertex 2: its faces form 3 fans, kept as 3 vertices at one position \(a crease/,
    );
    const copies = (v: number) => [...vertexOrigin.keys()].filter((i) => vertexOrigin[i] === v);
    const s = computeSharpness(cage, buildTopology(cage));
    expect(copies(1).length).toBe(3);
    for (const c of copies(1)) expect(s.vertex[c], `copy ${c} of vertex 2`).toBe(0);
    expect([...(cage.cornerExempt ?? [])].sort()).toEqual(copies(1).sort());
    // The line's ends are sharpened (one non-manifold edge each): every copy a corner.
    for (const v of [0, 2]) for (const c of copies(v)) expect(s.vertex[c]).toBe(SHARPNESS_INFINITE);
    // The two non-manifold edges became 6 edges (3 face sides each), all infinitely sharp.
    expect(cage.creases.filter((c) => c.sharpness === SHARPNESS_INFINITE).length).toBe(6);
    // Without the exemption the fin's copy of vertex 2 (one face) would be a corner.
    const plain = computeSharpness({ ...cage, cornerExempt: undefined }, buildTopology(cage));
    expect(copies(1).some((c) => plain.vertex[c] === SHARPNESS_INFINITE)).toBe(true);
  });

  it('crease and corner tags on a split vertex follow every copy', () => {
    // Two quads touching at vertex 0 (a bow tie), a crease on 0-1 and a corner tag at 0.
    const cage = makeCage(
      [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 0, 0, -1, -1, 0, 0, -1, 0],
      [
        [0, 1, 2, 3],
        [0, 4, 5, 6],
      ],
      { creases: [[0, 1, 2]], corners: [[0, 3]] },
    );
    const r = splitNonManifold(cage);
    expect(r.cage.positions.length / 3).toBe(8);
    expect([...r.vertexOrigin]).toEqual([0, 1, 2, 3, 4, 5, 6, 0]);
    // Vertex 0 is non-manifold (two fans): OpenSubdiv sharpens it; the corner tag is infinite on both copies.
    expect(r.cage.corners.map((c) => [c.v, c.sharpness])).toEqual([
      [0, SHARPNESS_INFINITE],
      [7, SHARPNESS_INFINITE],
    ]);
    expect(r.cage.creases.map((c) => [c.v0, c.v1, c.sharpness])).toEqual([[0, 1, Math.fround(2)]]);
    expect(() => buildTopology(r.cage)).not.toThrow();
  });

  it('a face folded onto itself is refused with its line; a quad of one vertex is taken (OpenSubdiv takes it)', () => {
    const head = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n';
    expect(() => loadCage(`${head}f 1 2 1 3\n`)).toThrow(/line 5: degenerate face: vertex 1 appears more than once/);
    const { cage, warnings } = loadCage(`${head}f 1 2 3 4\nf 3 3 3 3\n`);
    // Vertex 3: the first quad's fan and each of the 4 corners of the collapsed quad.
    expect(cage.positions.length / 3).toBe(4 + 4);
    expect(warnings.map(formatIssue).join('\n')).toMatch(/repeat a vertex in a row/);
  });
});
