// A cage made for single-crease patches (src/gpu/cc/single-crease.ts singleCrease): a cube whose faces
// are n × n grids, with horizontal crease loops round its sides. Away from the cube's corners
// every vertex of a loop is an interior valence-4 vertex with the crease running straight
// through it, so the faces along a loop are regular but for that one crease.
import { makeCage, type Cage } from '../../src/mesh/index.ts';
import type { Surface } from '../../src/subdiv/index.ts';

/** The exact limit at cage vertex v (of a quad cage): a face's corner, (u, v) = (0,0), (1,0), (1,1), (0,1). */
export function cornerLimit(S: Surface, cage: Cage, v: number) {
  const uv = [
    [0, 0],
    [1, 0],
    [1, 1],
    [0, 1],
  ];
  for (let f = 0; f < cage.faceOffsets.length - 1; f++)
    for (let j = 0; j < 4; j++) if (cage.faceIndices[cage.faceOffsets[f] + j] === v) return S.evaluate(f, uv[j][0], uv[j][1]);
  throw new Error(`vertex ${v} is in no face`);
}

/**
 * loops: [row, σ] with row in 1..n−1 the height of the loop (z = −1 + 2·row/n); loops must be 2
 * or more rows apart, and from the top and bottom, for every face along them to be single-crease.
 * Positions are jittered a little (deterministically) so nothing cancels by symmetry.
 */
export function creasedGridCube(n: number, loops: [number, number][], jitter = 0.03): Cage {
  const pos: number[] = [];
  const key = new Map<string, number>();
  const vert = (p: [number, number, number]): number => {
    const k = p.map((x) => Math.round(x * n * 2)).join(',');
    let i = key.get(k);
    if (i === undefined) {
      i = pos.length / 3;
      key.set(k, i);
      pos.push(...p);
    }
    return i;
  };
  // Each face: origin o, axes a, b (a × b outward).
  const sides: [number[], number[], number[]][] = [
    [
      [-1, -1, 1],
      [2, 0, 0],
      [0, 2, 0],
    ],
    [
      [-1, -1, -1],
      [0, 2, 0],
      [2, 0, 0],
    ],
    [
      [-1, -1, -1],
      [2, 0, 0],
      [0, 0, 2],
    ],
    [
      [1, -1, -1],
      [0, 2, 0],
      [0, 0, 2],
    ],
    [
      [1, 1, -1],
      [-2, 0, 0],
      [0, 0, 2],
    ],
    [
      [-1, 1, -1],
      [0, -2, 0],
      [0, 0, 2],
    ],
  ];
  const faces: number[][] = [];
  for (const [o, a, b] of sides) {
    const at = (i: number, j: number): number =>
      vert([0, 1, 2].map((x) => o[x] + (a[x] * i) / n + (b[x] * j) / n) as [number, number, number]);
    for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) faces.push([at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
  }
  const creases: [number, number, number][] = [];
  for (const [row, sigma] of loops) {
    const z = -1 + (2 * row) / n;
    const seen = new Set<string>();
    for (const f of faces)
      for (let k = 0; k < 4; k++) {
        const u = f[k],
          v = f[(k + 1) & 3];
        if (Math.abs(pos[3 * u + 2] - z) > 1e-9 || Math.abs(pos[3 * v + 2] - z) > 1e-9) continue;
        const s = `${Math.min(u, v)} ${Math.max(u, v)}`;
        if (seen.has(s)) continue;
        seen.add(s);
        creases.push([u, v, sigma]);
      }
  }
  let s = 7;
  const rnd = () => (s = (s * 16807) % 2147483647) / 2147483647 - 0.5;
  for (let i = 0; i < pos.length; i++) pos[i] += jitter * rnd();
  return makeCage(pos, faces, { creases });
}
