/** Small cages built in code for the GPU tests (the project's models live in public/models). */
import { makeCage, type Cage } from '../../src/mesh/types.ts';

/** A cube of quads. */
export function cube(): Cage {
  const p = [-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1];
  return makeCage(p, [
    [0, 3, 2, 1],
    [4, 5, 6, 7],
    [0, 1, 5, 4],
    [1, 2, 6, 5],
    [2, 3, 7, 6],
    [3, 0, 4, 7],
  ]);
}

/** An octahedron pushed out to a sphere: triangles, valence-4 vertices. */
export function octahedron(): Cage {
  const p = [1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1];
  return makeCage(p, [
    [0, 2, 4],
    [2, 1, 4],
    [1, 3, 4],
    [3, 0, 4],
    [2, 0, 5],
    [1, 2, 5],
    [3, 1, 5],
    [0, 3, 5],
  ]);
}

/** A torus of n × m quads (regular, closed). */
export function torus(n = 8, m = 6, R = 2, r = 0.7): Cage {
  const p: number[] = [];
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < m; j++) {
      const a = (2 * Math.PI * i) / n,
        b = (2 * Math.PI * j) / m;
      p.push((R + r * Math.cos(b)) * Math.cos(a), (R + r * Math.cos(b)) * Math.sin(a), r * Math.sin(b));
    }
  }
  const f: number[][] = [];
  const id = (i: number, j: number) => ((i + n) % n) * m + ((j + m) % m);
  for (let i = 0; i < n; i++) for (let j = 0; j < m; j++) f.push([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
  return makeCage(p, f);
}

/** An open, curved sheet of quads with a pentagon: boundary edges. */
export function sheet(): Cage {
  const p: number[] = [];
  const N = 4;
  for (let j = 0; j <= N; j++) for (let i = 0; i <= N; i++) p.push(i - N / 2, j - N / 2, 0.15 * ((i - N / 2) ** 2 - (j - N / 2) ** 2));
  const f: number[][] = [];
  for (let j = 0; j < N; j++)
    for (let i = 0; i < N; i++) f.push([j * (N + 1) + i, j * (N + 1) + i + 1, (j + 1) * (N + 1) + i + 1, (j + 1) * (N + 1) + i]);
  return makeCage(p, f);
}
