// Small test cages (0-based), embedded so the tests need no files outside the repository.
import { makeCage, type Cage } from '../../src/mesh/index.ts';

export const cubePos = [-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1];
export const cubeFaces = [
  [4, 5, 6, 7],
  [0, 3, 2, 1],
  [0, 1, 5, 4],
  [1, 2, 6, 5],
  [2, 3, 7, 6],
  [3, 0, 4, 7],
];

export function cube(tags: Parameters<typeof makeCage>[2] = {}, scale = 1): Cage {
  return makeCage(
    cubePos.map((x) => x * scale),
    cubeFaces,
    tags,
  );
}

export const ringCrease = (s: number): [number, number, number][] => [
  [4, 5, s],
  [5, 6, s],
  [6, 7, s],
  [7, 4, s],
];

export function fan(n: number): Cage {
  const p = [0, 0, 1];
  for (let i = 0; i < n; i++) p.push(Math.cos((2 * Math.PI * i) / n), Math.sin((2 * Math.PI * i) / n), 0);
  for (let i = 0; i < n; i++) p.push(1.5 * Math.cos((2 * Math.PI * (i + 0.5)) / n), 1.5 * Math.sin((2 * Math.PI * (i + 0.5)) / n), 0);
  const f: number[][] = [];
  for (let i = 0; i < n; i++) f.push([0, 1 + i, 1 + n + i, 1 + ((i + 1) % n)]);
  return makeCage(p, f);
}

export function grid3(): Cage {
  const H = [
    [0, 1, 0, 2],
    [1, 3, 2, 0],
    [0, 2, 1, 1],
    [2, 0, 1, 0],
  ];
  const p: number[] = [];
  for (let j = 0; j < 4; j++) for (let i = 0; i < 4; i++) p.push(i, j, H[j][i]);
  const f: number[][] = [];
  for (let j = 0; j < 3; j++) for (let i = 0; i < 3; i++) f.push([4 * j + i, 4 * j + i + 1, 4 * j + i + 5, 4 * j + i + 4]);
  return makeCage(p, f);
}

export function tetra(): Cage {
  return makeCage(
    [1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1],
    [
      [0, 1, 2],
      [0, 2, 3],
      [0, 3, 1],
      [1, 3, 2],
    ],
  );
}

export function triPrism(): Cage {
  const r = Math.sqrt(3) / 2;
  return makeCage(
    [1, 0, -1, -0.5, r, -1, -0.5, -r, -1, 1, 0, 1, -0.5, r, 1, -0.5, -r, 1],
    [
      [3, 4, 5],
      [0, 2, 1],
      [0, 1, 4, 3],
      [1, 2, 5, 4],
      [2, 0, 3, 5],
    ],
  );
}

export function pentPrism(): Cage {
  const p: number[] = [];
  for (const z of [-1, 1]) for (let i = 0; i < 5; i++) p.push(Math.cos((2 * Math.PI * i) / 5), Math.sin((2 * Math.PI * i) / 5), z);
  const f: number[][] = [
    [5, 6, 7, 8, 9],
    [4, 3, 2, 1, 0],
  ];
  for (let i = 0; i < 5; i++) f.push([i, (i + 1) % 5, 5 + ((i + 1) % 5), 5 + i]);
  return makeCage(p, f);
}

/** A torus of nu × nv quads, every vertex of valence 4: vertex (i, j) is j·nu + i, face (i, j)
 * runs (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1), indices wrapping round. */
export function quadTorus(nu: number, nv: number, tags: Parameters<typeof makeCage>[2] = {}): Cage {
  const p: number[] = [];
  for (let j = 0; j < nv; j++)
    for (let i = 0; i < nu; i++) {
      const u = (2 * Math.PI * i) / nu,
        v = (2 * Math.PI * j) / nv;
      p.push((2 + Math.cos(v)) * Math.cos(u), (2 + Math.cos(v)) * Math.sin(u), Math.sin(v));
    }
  const f: number[][] = [];
  for (let j = 0; j < nv; j++)
    for (let i = 0; i < nu; i++) {
      const a = j * nu + i,
        b = j * nu + ((i + 1) % nu),
        c = ((j + 1) % nv) * nu + ((i + 1) % nu),
        d = ((j + 1) % nv) * nu + i;
      f.push([a, b, c, d]);
    }
  return makeCage(p, f, tags);
}
