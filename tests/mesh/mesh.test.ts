import { describe, expect, it } from 'vitest';
import {
  CageError,
  formatIssue,
  FaceKind,
  FACE_FLAG_BOUNDARY,
  FACE_FLAG_CREASED,
  FACE_FLAG_SEMISHARP,
  SHARPNESS_INFINITE,
  buildTopology,
  classify,
  computeSharpness,
  loadCage,
  makeCage,
  parseObj,
  vertexRing,
  writeObj,
} from '../../src/mesh/index.ts';

const CUBE = `# cube
o cube
g g1
s 1
usemtl none
v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
vt 0 0
vt 1 0
vt 1 1
vn 0 0 1
f 5/1/1 6/2/1 7/3/1 8//1
f 1 4 3 2
f 1/1 2/2 6/3 5/1
f -7 -6 \\
  -2 -3
f 3 4 8 7
f 4 1 5 8
t crease 2/1/0 4 5 2.5
t crease 4/2/0 5 6 6 7 1 10
t corner 1/1/0 6 3
t interpolateboundary 1/0/0 2
t creasemethod 0/0/1 chaikin
t facevaryinginterpolateboundary 1/0/0 1
`;

function expectError(text: string, line: number, re: RegExp): void {
  try {
    loadCage(text);
  } catch (e) {
    expect(e).toBeInstanceOf(CageError);
    const issues = (e as CageError).issues;
    const hit = issues.find((i) => i.line === line && re.test(i.message));
    expect(hit, `wanted line ${line} ${re}, got ${JSON.stringify(issues)}`).toBeDefined();
    return;
  }
  throw new Error('expected a CageError');
}

describe('OBJ reader', () => {
  it('reads all index forms, negative indices, continuations and tags', () => {
    const { cage, topology, warnings } = loadCage(CUBE);
    expect(cage.positions.length).toBe(24);
    expect(Array.from(cage.faceOffsets)).toEqual([0, 4, 8, 12, 16, 20, 24]);
    expect(Array.from(cage.faceIndices.subarray(12, 16))).toEqual([1, 2, 6, 5]);
    expect(Array.from(cage.faceUvIndices.subarray(0, 4))).toEqual([0, 1, 2, -1]);
    expect(Array.from(cage.faceNormalIndices.subarray(0, 4))).toEqual([0, 0, 0, 0]);
    expect(cage.faceLines[3]).toBe(21);
    expect(cage.creases).toHaveLength(3);
    expect(cage.creases[0].sharpness).toBe(Math.fround(2.5));
    expect(cage.creases[2]).toMatchObject({ v0: 6, v1: 7, sharpness: SHARPNESS_INFINITE });
    expect(cage.corners[0]).toMatchObject({ v: 6, sharpness: 3 });
    expect(cage.fileOptions).toEqual({ boundary: 'edge-only', creasing: 'chaikin' });
    expect(cage.rawTags).toHaveLength(1);
    expect(topology.nEdges).toBe(12);
    expect(warnings.some((w) => /facevarying/.test(w.message))).toBe(true);
  });
  it('round-trips through writeObj', () => {
    const a = loadCage(CUBE).cage;
    const b = parseObj(writeObj(a)).cage;
    expect(Array.from(b.positions)).toEqual(Array.from(a.positions));
    expect(Array.from(b.faceIndices)).toEqual(Array.from(a.faceIndices));
    expect(Array.from(b.faceUvIndices)).toEqual(Array.from(a.faceUvIndices));
    expect(Array.from(b.faceNormalIndices)).toEqual(Array.from(a.faceNormalIndices));
    expect(b.creases.map(({ v0, v1, sharpness }) => [v0, v1, sharpness])).toEqual(
      a.creases.map(({ v0, v1, sharpness }) => [v0, v1, sharpness]),
    );
    expect(b.corners.map(({ v, sharpness }) => [v, sharpness])).toEqual(a.corners.map(({ v, sharpness }) => [v, sharpness]));
    expect(b.fileOptions).toEqual(a.fileOptions);
    expect(writeObj(b)).toBe(writeObj(a));
  });
  it('round-trips holes and awkward numbers', () => {
    const c = makeCage([0.1, 1e-300, -0, 1 / 3, 2, 3, 4, 5, 6e20], [[0, 1, 2]], { holes: [0], creases: [[0, 1, Math.fround(2.3)]] });
    const d = parseObj(writeObj(c)).cage;
    expect(Array.from(d.positions)).toEqual(Array.from(c.positions).map((x) => (Object.is(x, -0) ? 0 : x)));
    expect(d.holes).toEqual([0]);
    expect(d.creases[0].sharpness).toBe(Math.fround(2.3));
  });
});

describe('errors name the line and the problem', () => {
  const head = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n';
  it('malformed vertex / non-finite coordinates', () => {
    expectError('v 1 2\nf 1 1 1\n', 1, /3 coordinates/);
    expectError('v 1 nan 2\n', 1, /non-finite/);
    expectError('v 1 1e999 2\n', 1, /infinity/);
    expectError('v 1 abc 2\n', 1, /not a number/);
  });
  it('bad face indices', () => {
    expectError(head + 'f 1 2 0\n', 5, /index 0/);
    expectError(head + 'f 1 2 9\n', 5, /out of range/);
    expectError(head + 'f 1 2 -9\n', 5, /out of range/);
    expectError(head + 'f 1 2 x\n', 5, /not an integer/);
    expectError(head + 'f 1 2\n', 5, /at least 3/);
    expectError(head + 'f 1/1 2 3\n', 5, /texture coordinate index/);
    expectError(head + 'f 1//a 2 3\n', 5, /not an integer/);
  });
  it('degenerate faces', () => expectError(head + 'f 1 2 1 3\n', 5, /degenerate face/));
  it('unknown statements', () => expectError(head + 'xyz 1\nf 1 2 3\n', 5, /unknown statement/));
  it('empty file', () => {
    expectError('', 0, /empty/);
    expectError('# nothing\n\n', 0, /empty/);
    expectError(head, 0, /no faces/);
  });
  it('non-manifold edges and vertices, inconsistent winding: kept apart, sharp, as OpenSubdiv does, with a warning each', () => {
    const cases: [string, number, RegExp][] = [
      // Three faces on edge 1-2: each keeps its side (vertices 1 and 2 split in 3).
      [head + 'v 0 0 1\nv 1 0 -1\nf 1 2 3\nf 2 1 5\nf 1 2 6\n', 6 + 4, /line 9: non-manifold edge 1-2: shared by 3 faces/],
      // Edges 1-2 and 1-4 run the same way in two faces: vertices 1, 2 and 4 split in 2.
      [head + 'f 1 2 3\nf 1 3 4\nf 1 2 4\n', 4 + 3, /edge 1-2 runs the same way in faces 1 and 3/],
      // Two triangles touching at one vertex (bow tie).
      ['v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n', 5 + 1, /line 1: non-manifold vertex 1: its faces form 2 fans/],
    ];
    for (const [text, verts, warning] of cases) {
      const { cage, warnings } = loadCage(text);
      expect(cage.positions.length / 3).toBe(verts);
      expect(warnings.map(formatIssue).join('\n')).toMatch(warning);
      expect(cage.corners.length).toBeGreaterThan(0); // the non-manifold vertices: corners
    }
  });
  it('a face folded onto itself at a repeated vertex is refused; a zero-length edge is taken', () => {
    expectError(head + 'f 1 2 1 3\n', 5, /degenerate face: vertex 1 appears more than once/);
    const { cage, warnings } = loadCage(head + 'v 0.5 2 0\nf 1 2 3 3\nf 3 2 5\n');
    expect(warnings.map(formatIssue).join('\n')).toMatch(/repeats a vertex in a row: a zero-length edge/);
    expect(cage.positions.length / 3).toBe(6);
  });
  it('tags', () => {
    expectError(head + 'f 1 2 3 4\nt crease 2/1/0 0 2 1\n', 6, /not an edge/);
    expectError(head + 'f 1 2 3 4\nt crease 2/1/0 0 9 1\n', 6, /out of range/);
    expectError(head + 'f 1 2 3 4\nt crease 3/1/0 0 1 2 1\n', 6, /pairs/);
    expectError(head + 'f 1 2 3 4\nt crease 2/1/0 0 1\n', 6, /announce/);
    expectError(head + 'f 1 2 3 4\nt crease 2/1/0 0 1 -1\n', 6, /negative/);
    expectError(head + 'f 1 2 3 4\nt corner 1/1/0 7 1\n', 6, /out of range/);
    expectError(head + 'f 1 2 3 4\nt hole 1/0/0 3\n', 6, /out of range/);
    expectError(head + 'f 1 2 3 4\nt interpolateboundary 1/0/0 5\n', 6, /interpolateboundary/);
    expectError(head + 'f 1 2 3 4\nt creasemethod 0/0/1 weird\n', 6, /creasemethod/);
    expectError(head + 'f 1 2 3 4\nt crease x 0 1 1\n', 6, /nInt/);
  });
  it('lists every problem, sorted by line', () => {
    try {
      loadCage('v 1\nv 1 2 3\nf 1 0 2\n');
    } catch (e) {
      expect((e as CageError).issues.map((i) => i.line)).toEqual([1, 3]);
      expect((e as CageError).message).toMatch(/^line 1: /);
    }
  });
  it('accepts unused vertices with a warning', () => {
    const r = loadCage(head + 'v 5 5 5\nf 1 2 3 4\n');
    expect(r.warnings.some((w) => /not used/.test(w.message))).toBe(true);
  });
});

describe('topology and classification', () => {
  it("vertex rings follow OpenSubdiv's ordering", () => {
    const { topology: T } = loadCage(CUBE);
    for (let v = 0; v < 8; v++) {
      const r = vertexRing(T, v)!;
      expect(r.he).toHaveLength(3);
      expect(r.boundary).toBe(false);
      for (let i = 0; i < 3; i++) {
        const h = r.he[i],
          hn = r.he[(i + 1) % 3];
        // face i contains v->e_i and e_{i+1}->v
        expect(T.faceIndices[T.hePrev[h]]).toBe(T.faceIndices[T.heNext[hn]]);
      }
    }
  });
  it('boundary sharpening and corners', () => {
    // 3x1 strip: corners get infinite vertex sharpness under edge-and-corner only.
    const c = makeCage(
      [0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0, 3, 1, 0],
      [
        [0, 1, 5, 4],
        [1, 2, 6, 5],
        [2, 3, 7, 6],
      ],
    );
    const T = buildTopology(c);
    const s1 = computeSharpness(c, T, { boundary: 'edge-and-corner', creasing: 'uniform' });
    expect(Array.from(s1.vertex)).toEqual([10, 0, 0, 10, 10, 0, 0, 10]);
    expect(Array.from(s1.edge).every((s) => s === 0 || s === 10)).toBe(true);
    const s2 = computeSharpness(c, T, { boundary: 'edge-only', creasing: 'uniform' });
    expect(Array.from(s2.vertex).every((s) => s === 0)).toBe(true);
    const s3 = computeSharpness(c, T, { boundary: 'none', creasing: 'uniform' });
    expect(Array.from(s3.hole)).toEqual([1, 1, 1]);
  });
  it('classifies faces for the GPU', () => {
    // 4x4 closed torus grid with one triangle pair replacing a quad and a creased loop.
    const n = 5,
      p: number[] = [];
    for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) p.push(Math.cos(i), Math.sin(i), j);
    const id = (i: number, j: number): number => ((j + n) % n) * n + ((i + n) % n);
    const f: number[][] = [];
    for (let j = 0; j < n; j++)
      for (let i = 0; i < n; i++) {
        if (i === 0 && j === 0) {
          f.push([id(0, 0), id(1, 0), id(1, 1)], [id(0, 0), id(1, 1), id(0, 1)]);
          continue;
        }
        f.push([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
      }
    const creases: [number, number, number][] = [];
    for (let i = 0; i < n; i++) creases.push([id(i, 3), id(i + 1, 3), 2]);
    const c = makeCage(p, f, { creases });
    const T = buildTopology(c);
    const K = classify(T, computeSharpness(c, T));
    expect(K.faceKind[0]).toBe(FaceKind.NonQuad);
    expect(K.faceKind[1]).toBe(FaceKind.NonQuad);
    // Quad (1,0) shares vertices with the triangles.
    expect(K.faceKind[2]).toBe(FaceKind.QuadNextToNonQuad);
    // Vertex (0,0) and (1,1) have valence 5 / 3 ... quads touching them far from triangles? all touch; pick (3,1).
    const fid = (i: number, j: number): number => (j === 0 ? (i === 0 ? 0 : i + 1) : j * n + i + 1);
    expect(K.faceKind[fid(3, 1)]).toBe(FaceKind.Regular);
    expect(K.faceKind[fid(3, 2)]).toBe(FaceKind.QuadIrregular); // semi-sharp crease at row 3
    expect(K.faceFlags[fid(3, 2)] & FACE_FLAG_SEMISHARP).toBeTruthy();
    expect(K.faceFlags[fid(3, 2)] & FACE_FLAG_CREASED).toBeTruthy();
    expect(K.faceFlags[fid(3, 1)] & FACE_FLAG_BOUNDARY).toBeFalsy();
  });
});
