// The CPU half of the cage stand-in and of the cage overlay (src/gpu/render/cage-mesh.ts).
import { describe, expect, it } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';
import { makeCage } from '../../../src/mesh/types.ts';
import { loadCage } from '../../../src/mesh/index.ts';
import { BARY_CORNER1, BARY_CORNER2 } from '../../../src/gpu/contract/tessellated-mesh.ts';
import { cageEdges, cageLineVertices, CAGE_LINE_STRIDE, triangulateCage } from '../../../src/gpu/render/cage-mesh.ts';

// A unit cube, faces counter-clockwise seen from outside.
const cube = makeCage(
  [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1],
  [
    [0, 3, 2, 1],
    [4, 5, 6, 7],
    [0, 1, 5, 4],
    [1, 2, 6, 5],
    [2, 3, 7, 6],
    [3, 0, 4, 7],
  ],
  {
    creases: [
      [0, 1, 10],
      [1, 2, 2.5],
    ],
  },
);

describe('triangulateCage', () => {
  it('fans every face: n − 2 triangles each, corners from the face', () => {
    const t = triangulateCage(cube);
    expect(t.triangleCount).toBe(12);
    expect(t.vertexCount).toBe(8);
    expect(Array.from(t.indices.slice(0, 6))).toEqual([0, 3, 2, 0, 2, 1]);
    expect(t.positions).toEqual(Float32Array.from(cube.positions));
  });

  it('gives unit, outward, area-weighted normals (the corner diagonal on a cube)', () => {
    const t = triangulateCage(cube);
    for (let v = 0; v < 8; v++) {
      const n = [t.normals[3 * v], t.normals[3 * v + 1], t.normals[3 * v + 2]];
      expect(Math.hypot(...n)).toBeCloseTo(1, 6);
      const outward = [0, 1, 2].map((k) => cube.positions[3 * v + k] - 0.5);
      // Each corner touches three faces; fans split them unevenly, but the normal still points out.
      expect(n[0] * outward[0] + n[1] * outward[1] + n[2] * outward[2]).toBeGreaterThan(0.4);
    }
    // A pyramid apex over a square: the normal sums the four sloped faces.
    const pyr = makeCage(
      [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1],
      [
        [0, 3, 2, 1],
        [0, 1, 4],
        [1, 2, 4],
        [2, 3, 4],
        [3, 0, 4],
      ],
    );
    const p = triangulateCage(pyr);
    expect(p.normals[12]).toBeCloseTo(0, 6);
    expect(p.normals[13]).toBeCloseTo(0, 6);
    expect(p.normals[14]).toBeCloseTo(1, 6);
  });

  it('records for each vertex a source triangle in which it is a corner, with the corner code', () => {
    const t = triangulateCage(cube);
    const codes = [0, BARY_CORNER1, BARY_CORNER2];
    for (let v = 0; v < t.vertexCount; v++) {
      const tri = t.srcTri[v];
      const corner = [0, 1, 2].find((c) => t.indices[3 * tri + c] === v);
      expect(corner).toBeDefined();
      expect(t.bary[v]).toBe(codes[corner!]);
    }
  });

  it('drops hole faces', () => {
    const holed = makeCage(
      cube.positions,
      [
        [0, 3, 2, 1],
        [4, 5, 6, 7],
        [0, 1, 5, 4],
        [1, 2, 6, 5],
        [2, 3, 7, 6],
        [3, 0, 4, 7],
      ],
      { holes: [1] },
    );
    expect(triangulateCage(holed).triangleCount).toBe(10);
  });

  it('handles every project model (triangle counts, finite unit normals)', () => {
    const dir = new URL('../../../public/models/', import.meta.url);
    const files = readdirSync(dir).filter((f) => f.endsWith('.obj'));
    for (const f of files) {
      const { cage } = loadCage(readFileSync(new URL(f, dir), 'utf8'));
      const t = triangulateCage(cage);
      let expected = 0;
      const holes = new Set(cage.holes);
      for (let i = 0; i + 1 < cage.faceOffsets.length; i++)
        if (!holes.has(i)) expected += cage.faceOffsets[i + 1] - cage.faceOffsets[i] - 2;
      expect(t.triangleCount, f).toBe(expected);
      for (let v = 0; v < t.vertexCount; v++) {
        const len = Math.hypot(t.normals[3 * v], t.normals[3 * v + 1], t.normals[3 * v + 2]);
        expect(len === 0 || Math.abs(len - 1) < 1e-5, `${f} vertex ${v}`).toBe(true);
      }
    }
  });
});

describe('cage overlay', () => {
  it('lists each polygon edge once, not the triangulation diagonals', () => {
    const { pairs, sharpness } = cageEdges(cube);
    expect(pairs.length / 2).toBe(12);
    const keys = new Set<string>();
    for (let e = 0; e < pairs.length / 2; e++) keys.add([pairs[2 * e], pairs[2 * e + 1]].sort().join('-'));
    expect(keys.size).toBe(12);
    expect(keys.has('0-2')).toBe(false);
    const sharp = Object.fromEntries([...keys].map((k, e) => [k, sharpness[e]]));
    expect(sharp['0-1']).toBe(10);
    expect(sharp['1-2']).toBe(2.5);
    expect(sharp['4-5']).toBe(0);
  });

  it('packs two vertices per edge, position then RGBA8 colour, creases coloured apart', () => {
    const { data, vertexCount, edgeCount } = cageLineVertices(cube);
    expect(edgeCount).toBe(12);
    expect(vertexCount).toBe(24);
    expect(data.byteLength).toBe(24 * CAGE_LINE_STRIDE);
    const f32 = new Float32Array(data);
    const u8 = new Uint8Array(data);
    const { pairs, sharpness } = cageEdges(cube);
    const colour = (i: number) => Array.from(u8.slice(i * CAGE_LINE_STRIDE + 12, i * CAGE_LINE_STRIDE + 16));
    for (let i = 0; i < vertexCount; i++) {
      const v = pairs[i];
      expect(Array.from(f32.slice(i * 4, i * 4 + 3))).toEqual([
        cube.positions[3 * v],
        cube.positions[3 * v + 1],
        cube.positions[3 * v + 2],
      ]);
      expect(colour(i)[3]).toBe(255);
    }
    const smooth = sharpness.indexOf(0);
    const crease = sharpness.indexOf(10);
    expect(colour(2 * smooth)).not.toEqual(colour(2 * crease));
    expect(colour(2 * smooth)).toEqual(colour(2 * smooth + 1));
  });
});
