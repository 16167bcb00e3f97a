// Generates tessellab's own subdivision cages into public/models/ (npm run models).
// Every model is built here from scratch; see public/models/README.md.
import { mkdirSync, writeFileSync } from 'node:fs';
import { type Cage, loadCage, makeCage, turnUpAxis, uvCoverage, uvSeams, writeObj } from '../src/mesh/index.ts';
import { type HeightMap, type HeightWrap, heightMapFromFunction } from '../src/mesh/heightmap.ts';
import { encodeHeightPng } from '../src/mesh/heightmap-png.ts';

type V3 = [number, number, number];
const r6 = (x: number): number => Math.round(x * 1e6) / 1e6 + 0; // short, exact-in-file coordinates

class Builder {
  v: V3[] = [];
  f: number[][] = [];
  creases: [number, number, number][] = [];
  corners: [number, number][] = [];
  add(p: V3): number {
    this.v.push([r6(p[0]), r6(p[1]), r6(p[2])]);
    return this.v.length - 1;
  }
  face(...ids: number[]): number {
    this.f.push(ids);
    return this.f.length - 1;
  }
  /** Extrude face fi along `off`, scaling its new cap by `s` about the centroid; returns the cap face id. */
  extrude(fi: number, off: V3, s = 1): number {
    const face = this.f[fi];
    const c = centroid(face.map((i) => this.v[i]));
    const nv = face.map((i) => this.add([0, 1, 2].map((k) => c[k] + s * (this.v[i][k] - c[k]) + off[k]) as V3));
    for (let j = 0; j < face.length; j++) {
      const j1 = (j + 1) % face.length;
      this.face(face[j], face[j1], nv[j1], nv[j]);
    }
    this.f[fi] = nv;
    return fi;
  }
  normal(fi: number): V3 {
    const p = this.f[fi].map((i) => this.v[i]);
    const n: V3 = [0, 0, 0];
    for (let j = 0; j < p.length; j++) {
      const a = p[j],
        b = p[(j + 1) % p.length];
      n[0] += (a[1] - b[1]) * (a[2] + b[2]);
      n[1] += (a[2] - b[2]) * (a[0] + b[0]);
      n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    const l = Math.hypot(...n);
    return [n[0] / l, n[1] / l, n[2] / l];
  }
  /** Split every face into quads at edge midpoints and centroid (no smoothing); tags are carried. */
  linearSplit(): void {
    const mid = new Map<string, number>();
    const old = this.f;
    const key = (a: number, b: number): string => (a < b ? `${a},${b}` : `${b},${a}`);
    const m = (a: number, b: number): number => {
      const k = key(a, b);
      let id = mid.get(k);
      if (id === undefined) {
        id = this.add(centroid([this.v[a], this.v[b]]));
        mid.set(k, id);
      }
      return id;
    };
    this.f = [];
    for (const face of old) {
      const c = this.add(centroid(face.map((i) => this.v[i])));
      const n = face.length;
      for (let j = 0; j < n; j++) this.face(face[j], m(face[j], face[(j + 1) % n]), c, m(face[(j + n - 1) % n], face[j]));
    }
    const cr = this.creases;
    this.creases = [];
    for (const [a, b, s] of cr) {
      const x = m(a, b);
      this.creases.push([a, x, s], [x, b, s]);
    }
  }
  /** Replace face fi by a fan of triangles around its (offset) centroid. */
  poke(fi: number, off = 0): void {
    const face = this.f[fi];
    const c = centroid(face.map((i) => this.v[i]));
    const n = this.normal(fi);
    const ci = this.add([c[0] + off * n[0], c[1] + off * n[1], c[2] + off * n[2]]);
    this.f[fi] = [face[0], face[1], ci];
    for (let j = 1; j < face.length; j++) this.face(face[j], face[(j + 1) % face.length], ci);
  }
  cage(): ReturnType<typeof makeCage> {
    return makeCage(this.v.flat(), this.f, { creases: this.creases, corners: this.corners });
  }
}

function centroid(p: V3[]): V3 {
  const c: V3 = [0, 0, 0];
  for (const q of p) for (let k = 0; k < 3; k++) c[k] += q[k] / p.length;
  return c;
}

/** Box [-1,1]x[-0.75,0.75]x[-0.5,0.5] with each face split 2x2; creased rims and a sharp corner. */
function creasedBox(): Builder {
  const b = new Builder();
  const s: V3 = [1, 0.75, 0.5];
  const c = [
    [-1, -1, -1],
    [1, -1, -1],
    [1, 1, -1],
    [-1, 1, -1],
    [-1, -1, 1],
    [1, -1, 1],
    [1, 1, 1],
    [-1, 1, 1],
  ];
  for (const p of c) b.add([p[0] * s[0], p[1] * s[1], p[2] * s[2]]);
  for (const q of [
    [4, 5, 6, 7],
    [0, 3, 2, 1],
    [0, 1, 5, 4],
    [1, 2, 6, 5],
    [2, 3, 7, 6],
    [3, 0, 4, 7],
  ])
    b.face(...q);
  b.creases.push([4, 5, 2.5], [5, 6, 2.5], [6, 7, 2.5], [7, 4, 2.5]); // top rim: semi-sharp
  b.creases.push([0, 1, 10], [1, 2, 10], [2, 3, 10], [3, 0, 10]); // bottom rim: infinitely sharp
  b.creases.push([1, 5, 1.5]); // one vertical edge, fractional
  b.linearSplit();
  b.corners.push([6, 10]); // top corner (+x,+y,+z): sharp
  return b;
}

function torus(nu = 16, nv = 8, R = 1, r = 0.4): Builder {
  const b = new Builder();
  for (let j = 0; j < nv; j++)
    for (let i = 0; i < nu; i++) {
      const a = (2 * Math.PI * i) / nu,
        t = (2 * Math.PI * j) / nv;
      b.add([(R + r * Math.cos(t)) * Math.cos(a), (R + r * Math.cos(t)) * Math.sin(a), r * Math.sin(t)]);
    }
  const id = (i: number, j: number): number => ((j + nv) % nv) * nu + ((i + nu) % nu);
  for (let j = 0; j < nv; j++) for (let i = 0; i < nu; i++) b.face(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return b;
}

/** Chess pawn by revolution: 16 segments, n-gon base, triangle-fan top, rims as creases. */
function pawn(seg = 16): Builder {
  const b = new Builder();
  // Profile (radius, height) from the base rim upwards.
  const prof: [number, number, number][] = [
    // r, z, crease sharpness of this ring (0 none)
    [0.9, 0, 10],
    [0.9, 0.12, 0],
    [0.78, 0.2, 2],
    [0.62, 0.26, 0],
    [0.55, 0.36, 0],
    [0.42, 0.6, 0],
    [0.34, 0.95, 0],
    [0.5, 1.08, 3],
    [0.5, 1.14, 3],
    [0.3, 1.2, 0],
    [0.36, 1.3, 0],
    [0.46, 1.45, 0],
    [0.46, 1.62, 0],
    [0.36, 1.78, 0],
    [0.18, 1.88, 0],
  ];
  const ring: number[][] = [];
  for (const [r, z] of prof) {
    const row: number[] = [];
    for (let i = 0; i < seg; i++) {
      const a = (2 * Math.PI * i) / seg;
      row.push(b.add([r * Math.cos(a), r * Math.sin(a), z]));
    }
    ring.push(row);
  }
  const top = b.add([0, 0, 1.92]);
  b.face(...[...ring[0]].reverse()); // base: one n-gon, facing down
  for (let k = 0; k + 1 < ring.length; k++)
    for (let i = 0; i < seg; i++) {
      const i1 = (i + 1) % seg;
      b.face(ring[k][i], ring[k][i1], ring[k + 1][i1], ring[k + 1][i]);
    }
  const last = ring[ring.length - 1];
  for (let i = 0; i < seg; i++) b.face(last[i], last[(i + 1) % seg], top);
  prof.forEach(([, , s], k) => {
    if (s > 0) for (let i = 0; i < seg; i++) b.creases.push([ring[k][i], ring[k][(i + 1) % seg], s]);
  });
  return b;
}

/** Gear: 10 teeth, axle hole, n-gon top/bottom faces; valence 3, 4, 5 and 6 vertices. */
function gear(teeth = 10): Builder {
  const b = new Builder();
  const h = 0.18,
    rIn = 0.3,
    rRoot = 0.8,
    rTip = 1.0;
  const D = (2 * Math.PI) / teeth;
  const outline: [number, number][] = []; // angle, radius
  const inner: number[][] = []; // per tooth: angles of its inner points
  for (let i = 0; i < teeth; i++) {
    const a = i * D;
    outline.push([a, rRoot], [a + 0.3 * D, rTip], [a + 0.55 * D, rTip], [a + 0.8 * D, rRoot]);
    inner.push(i % 2 === 0 ? [a, a + 0.35 * D, a + 0.65 * D] : [a, a + 0.5 * D]);
  }
  const innerFlat = inner.flat();
  const build = (z: number): { o: number[]; n: number[] } => ({
    o: outline.map(([a, r]) => b.add([r * Math.cos(a), r * Math.sin(a), z])),
    n: innerFlat.map((a) => b.add([rIn * Math.cos(a), rIn * Math.sin(a), z])),
  });
  const T = build(h),
    B = build(-h);
  const faces = (L: { o: number[]; n: number[] }, flip: boolean): void => {
    const add = (ids: number[]): void => {
      b.face(...(flip ? [...ids].reverse() : ids));
    };
    let k = 0;
    const nIn = innerFlat.length,
      nOut = outline.length;
    for (let i = 0; i < teeth; i++) {
      const o0 = L.o[4 * i],
        ins = inner[i].map((_, j) => L.n[k + j]);
      for (let j = 0; j + 1 < ins.length; j++) add([ins[j], o0, ins[j + 1]]); // fan at the tooth root: valence 5/6
      const next = L.n[(k + ins.length) % nIn];
      add([ins[ins.length - 1], o0, L.o[4 * i + 1], L.o[4 * i + 2], L.o[4 * i + 3], L.o[(4 * i + 4) % nOut], next]); // 7-gon
      k += ins.length;
    }
  };
  faces(T, false);
  faces(B, true);
  const n = outline.length,
    m = innerFlat.length;
  for (let i = 0; i < n; i++) {
    const i1 = (i + 1) % n;
    b.face(B.o[i], B.o[i1], T.o[i1], T.o[i]);
  }
  for (let i = 0; i < m; i++) {
    const i1 = (i + 1) % m;
    b.face(B.n[i1], B.n[i], T.n[i], T.n[i1]);
  }
  for (let i = 0; i < n; i++) {
    const i1 = (i + 1) % n;
    b.creases.push([T.o[i], T.o[i1], 2], [B.o[i], B.o[i1], 2]);
  }
  for (let i = 0; i < m; i++) {
    const i1 = (i + 1) % m;
    b.creases.push([T.n[i], T.n[i1], 10], [B.n[i], B.n[i1], 10]);
  }
  return b;
}

/** Icosphere: icosahedron split once (80 triangles) on the unit sphere, with one pentagonal cap. */
function icosphere(): Builder {
  const b = new Builder();
  const t = (1 + Math.sqrt(5)) / 2;
  const base: V3[] = [
    [-1, t, 0],
    [1, t, 0],
    [-1, -t, 0],
    [1, -t, 0],
    [0, -1, t],
    [0, 1, t],
    [0, -1, -t],
    [0, 1, -t],
    [t, 0, -1],
    [t, 0, 1],
    [-t, 0, -1],
    [-t, 0, 1],
  ];
  const unit = (p: V3): V3 => {
    const l = Math.hypot(...p);
    return [p[0] / l, p[1] / l, p[2] / l];
  };
  for (const p of base) b.add(unit(p));
  const F = [
    [0, 11, 5],
    [0, 5, 1],
    [0, 1, 7],
    [0, 7, 10],
    [0, 10, 11],
    [1, 5, 9],
    [5, 11, 4],
    [11, 10, 2],
    [10, 7, 6],
    [7, 1, 8],
    [3, 9, 4],
    [3, 4, 2],
    [3, 2, 6],
    [3, 6, 8],
    [3, 8, 9],
    [4, 9, 5],
    [2, 4, 11],
    [6, 2, 10],
    [8, 6, 7],
    [9, 8, 1],
  ];
  const mid = new Map<string, number>();
  const m = (a: number, c: number): number => {
    const k = a < c ? `${a},${c}` : `${c},${a}`;
    let id = mid.get(k);
    if (id === undefined) {
      id = b.add(unit(centroid([b.v[a], b.v[c]])));
      mid.set(k, id);
    }
    return id;
  };
  for (const [a, c, d] of F) {
    const ab = m(a, c),
      bc = m(c, d),
      ca = m(d, a);
    b.face(a, ab, ca);
    b.face(ab, c, bc);
    b.face(ca, bc, d);
    b.face(ab, bc, ca);
  }
  // Merge the five triangles around vertex 0 into one pentagon (a flat-ish cap).
  const around = b.f.map((f, i) => ({ f, i })).filter(({ f }) => f.includes(0));
  const ring: number[] = [];
  // Outer edges of the fan, in order.
  const nextOf = new Map<number, number>();
  for (const { f } of around) {
    const j = f.indexOf(0);
    nextOf.set(f[(j + 1) % 3], f[(j + 2) % 3]);
  }
  let cur = around[0].f[(around[0].f.indexOf(0) + 1) % 3];
  for (let k = 0; k < 5; k++) {
    ring.push(cur);
    cur = nextOf.get(cur)!;
  }
  const drop = new Set(around.map(({ i }) => i));
  b.f = b.f.filter((_, i) => !drop.has(i));
  b.f.push(ring);
  // Vertex 0 is now unused; rebuild without it.
  const keep = b.v.map((_, i) => i).filter((i) => i !== 0);
  const remap = new Map(keep.map((v, i) => [v, i]));
  b.v = keep.map((i) => b.v[i]);
  b.f = b.f.map((f) => f.map((i) => remap.get(i)!));
  return b;
}

/** Open wavy sheet (boundary, corners interpolated), with an infinitely sharp fold line and a semi-sharp ridge. */
function sheet(nx = 8, ny = 6): Builder {
  const b = new Builder();
  for (let j = 0; j <= ny; j++)
    for (let i = 0; i <= nx; i++) {
      const x = (i / nx) * 2 - 1,
        y = (j / ny) * 1.5 - 0.75;
      b.add([x, y, 0.15 * Math.sin(3 * x) * Math.cos(2 * y) + (i === 4 ? 0.2 : 0)]);
    }
  const id = (i: number, j: number): number => j * (nx + 1) + i;
  for (let j = 0; j < ny; j++) for (let i = 0; i < nx; i++) b.face(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  for (let j = 0; j < ny; j++) b.creases.push([id(4, j), id(4, j + 1), 10]); // fold across the sheet (ends on the boundary)
  for (let i = 1; i < 3; i++) b.creases.push([id(i, 3), id(i + 1, 3), 1.7]); // short semi-sharp ridge (crease ends)
  return b;
}

/** Box-modelled four-legged creature: body, legs, neck, head, tail, ears, eyes. */
function creature(): Builder {
  const b = new Builder();
  // Body: 3x2x2 boxes (quads), x forward.
  const nx = 3,
    ny = 2,
    nz = 2;
  const sx = 1.2,
    sy = 0.5,
    sz = 0.45;
  const grid = new Map<string, number>();
  const P = (i: number, j: number, k: number): number => {
    const key = `${i},${j},${k}`;
    let id = grid.get(key);
    if (id === undefined) {
      const bulge = 1 + 0.15 * Math.sin((Math.PI * i) / nx);
      id = b.add([(-1 + (2 * i) / nx) * sx, (-1 + (2 * j) / ny) * sy * bulge, (-1 + (2 * k) / nz) * sz * bulge + 1.2]);
      grid.set(key, id);
    }
    return id;
  };
  const faceAt: Record<string, number> = {};
  for (let j = 0; j < ny; j++)
    for (let i = 0; i < nx; i++) {
      faceAt[`top${i},${j}`] = b.face(P(i, j, nz), P(i + 1, j, nz), P(i + 1, j + 1, nz), P(i, j + 1, nz));
      faceAt[`bot${i},${j}`] = b.face(P(i, j, 0), P(i, j + 1, 0), P(i + 1, j + 1, 0), P(i + 1, j, 0));
    }
  for (let k = 0; k < nz; k++)
    for (let i = 0; i < nx; i++) {
      b.face(P(i, 0, k), P(i + 1, 0, k), P(i + 1, 0, k + 1), P(i, 0, k + 1));
      b.face(P(i, ny, k), P(i, ny, k + 1), P(i + 1, ny, k + 1), P(i + 1, ny, k));
    }
  for (let k = 0; k < nz; k++)
    for (let j = 0; j < ny; j++) {
      faceAt[`front${j},${k}`] = b.face(P(nx, j, k), P(nx, j + 1, k), P(nx, j + 1, k + 1), P(nx, j, k + 1));
      faceAt[`back${j},${k}`] = b.face(P(0, j, k), P(0, j, k + 1), P(0, j + 1, k + 1), P(0, j + 1, k));
    }
  // Legs: extrude the four bottom corner faces down in three steps.
  for (const key of ['bot0,0', 'bot0,1', `bot${nx - 1},0`, `bot${nx - 1},1`]) {
    const f = faceAt[key];
    b.extrude(f, [0, 0, -0.15], 0.8);
    b.extrude(f, [0, 0, -0.45], 0.9);
    b.extrude(f, [0.05, 0, -0.4], 0.85);
    b.extrude(f, [0.12, 0, -0.1], 1.1); // foot
  }
  // Neck and head from the upper front face.
  let head = faceAt[`front0,1`];
  // Use the upper-front face pair: merge by extruding one of them only, the other stays as chest.
  b.extrude(head, [0.35, 0.25, 0.35], 0.85);
  b.extrude(head, [0.3, 0, 0.35], 0.9);
  b.extrude(head, [0.25, 0, 0.1], 1.35); // skull
  b.extrude(head, [0.35, 0, -0.05], 0.95);
  b.extrude(head, [0.35, 0, -0.12], 0.6); // snout
  head = faceAt[`front1,1`];
  b.extrude(head, [0.1, 0, 0.05], 0.8); // chest bump
  // Tail from the upper back face, curling up.
  const tail = faceAt[`back1,1`];
  for (let k = 0; k < 5; k++) b.extrude(tail, [-0.3, 0, 0.12 * k], 0.75);
  b.linearSplit();
  // Ears and eyes: poke faces on the skull into triangle fans (adds triangles / valence-3-ish tips).
  const skullTop: number[] = [];
  let best = -Infinity;
  b.f.forEach((f, i) => {
    const c = centroid(f.map((v) => b.v[v]));
    if (c[0] > 1.8 && c[2] > best - 0.25) {
      skullTop.push(i);
      best = Math.max(best, c[2]);
    }
  });
  const tops = skullTop
    .map((i) => ({ i, c: centroid(b.f[i].map((v) => b.v[v])) }))
    .filter(({ i }) => b.f[i].length === 4)
    .sort((a, z) => z.c[2] - a.c[2]);
  const ears = [tops.find(({ c }) => c[1] > 0.05), tops.find(({ c }) => c[1] < -0.05)];
  for (const e of ears) if (e) b.poke(e.i, 0.35);
  const eyes = b.f
    .map((f, i) => ({ i, f, c: centroid(f.map((v) => b.v[v])) }))
    .filter(({ f, c }) => f.length === 4 && c[0] > 2.1 && Math.abs(c[1]) > 0.1)
    .sort((a, z) => z.c[2] - a.c[2])
    .slice(0, 2);
  for (const e of eyes) b.poke(e.i, 0.05);
  return b;
}

// ---------------------------------------------------------------------------------------------
// Displaced models: a cage with face-varying UVs plus a height map generated here (written as a
// PNG by pngjs). Heights are h = (sample − midLevel)·scale along the limit normal (src/subdiv/displace.ts).

/** Attach per-corner uvs (one [u, v] per face corner, in face order); equal values share one vt line. */
function withCornerUvs(cage: Cage, uvOf: (face: number, corner: number) => [number, number]): Cage {
  const ids = new Map<string, number>();
  const uvs: number[] = [];
  const idx = new Int32Array(cage.faceIndices.length);
  for (let f = 0; f + 1 < cage.faceOffsets.length; f++) {
    for (let h = cage.faceOffsets[f]; h < cage.faceOffsets[f + 1]; h++) {
      const [u, v] = uvOf(f, h - cage.faceOffsets[f]).map(r6);
      const key = `${u},${v}`;
      let id = ids.get(key);
      if (id === undefined) {
        id = uvs.length / 2;
        ids.set(key, id);
        uvs.push(u, v);
      }
      idx[h] = id;
    }
  }
  return { ...cage, uvs: Float64Array.from(uvs), faceUvIndices: idx };
}

const smoothstep = (a: number, b: number, x: number): number => {
  const t = Math.min(1, Math.max(0, (x - a) / (b - a)));
  return t * t * (3 - 2 * t);
};
/** Integer hash to [0, 1) (deterministic, no Math.random). */
function hash01(...k: number[]): number {
  let h = 0x811c9dc5;
  for (const x of k) {
    h = Math.imul(h ^ (x | 0), 0x01000193);
    h ^= h >>> 15;
    h = Math.imul(h, 0x2c1b3c6d);
    h ^= h >>> 12;
  }
  return (h >>> 0) / 4294967296;
}

interface DisplacedModel {
  name: string;
  desc: string;
  cage: Cage;
  map: HeightMap;
  scale: number;
  midLevel: number;
  wrap: HeightWrap;
}

/**
 * Brick box: the creased box (same cage, same tags) with a box unwrap (each of the 6 sides its
 * own uv island in a 3 x 2 atlas at one texel density, so every box edge is a UV seam) and an
 * 8-bit 512 x 256 brick map: courses run round the four sides at the same heights, paving on
 * top and bottom; mortar sunk, bricks bevelled, each brick's height varied a little.
 * Island borders are padded by edge extension so bilinear lookups do not bleed across islands.
 */
function brickBox(): DisplacedModel {
  const b = creasedBox();
  const W = 512,
    H = 256,
    pad = 0.1;
  // Side → (a, b) local coordinates (a × b = outward normal, so no island is mirrored) and its atlas cell.
  type Side = { n: V3; ab: (p: V3) => [number, number]; min: [number, number]; size: [number, number]; at: [number, number] };
  const sides: Side[] = [
    { n: [0, 0, 1], ab: (p) => [p[0], p[1]], min: [-1, -0.75], size: [2, 1.5], at: [pad, 2 * pad + 1] },
    { n: [0, 0, -1], ab: (p) => [p[0], -p[1]], min: [-1, -0.75], size: [2, 1.5], at: [2 * pad + 2, 2 * pad + 1] },
    { n: [1, 0, 0], ab: (p) => [p[1], p[2]], min: [-0.75, -0.5], size: [1.5, 1], at: [3 * pad + 4, 2 * pad + 1] },
    { n: [0, 1, 0], ab: (p) => [-p[0], p[2]], min: [-1, -0.5], size: [2, 1], at: [pad, pad] },
    { n: [0, -1, 0], ab: (p) => [p[0], p[2]], min: [-1, -0.5], size: [2, 1], at: [2 * pad + 2, pad] },
    { n: [-1, 0, 0], ab: (p) => [-p[1], p[2]], min: [-0.75, -0.5], size: [1.5, 1], at: [3 * pad + 4, pad] },
  ];
  const rho = Math.min(W / (5.5 + 4 * pad), H / (2.5 + 3 * pad)); // texels per world unit
  const cage0 = b.cage();
  const sideOf = (f: number): Side => {
    const n = b.normal(f);
    return sides.reduce((best, s) =>
      s.n[0] * n[0] + s.n[1] * n[1] + s.n[2] * n[2] > best.n[0] * n[0] + best.n[1] * n[1] + best.n[2] * n[2] ? s : best,
    );
  };
  const cage = withCornerUvs(cage0, (f, j) => {
    const s = sideOf(f);
    const [a, c] = s.ab(b.v[b.f[f][j]]);
    return [((s.at[0] + a - s.min[0]) * rho) / W, ((s.at[1] + c - s.min[1]) * rho) / H];
  });
  const course = 0.125,
    brick = 0.25,
    mortar = 0.02,
    // The bevel: over 4 texels, so that a tessellation of a segment per texel or two, whose
    // triangles do not line up with the courses, follows it without saw teeth (0.025 over 2
    // texels, and the relief at 0.06, left teeth along every brick's top edge at the default view).
    BEVEL = 0.03;
  const bricks = (a: number, c: number, paving: boolean): number => {
    const row = Math.floor(c / course);
    const x = a + (row % 2 === 0 ? 0 : brick / 2);
    const col = Math.floor(x / (paving ? course * 2 : brick));
    const fx = x - col * (paving ? course * 2 : brick),
      fy = c - row * course;
    const d = Math.min(fx, (paving ? course * 2 : brick) - fx, fy, course - fy);
    const top = 0.78 + 0.14 * (hash01(row, col, paving ? 1 : 0) - 0.5);
    return 0.15 + (top - 0.15) * smoothstep(mortar / 2, mortar / 2 + BEVEL, d);
  };
  const map = heightMapFromFunction(W, H, 8, (u, v) => {
    const X = (u * W) / rho,
      Y = (v * H) / rho;
    // Nearest island (distance to its rectangle), then clamp into it: edge-extended padding.
    let best = sides[0],
      bd = Infinity;
    for (const s of sides) {
      const dx = Math.max(s.at[0] - X, 0, X - (s.at[0] + s.size[0])),
        dy = Math.max(s.at[1] - Y, 0, Y - (s.at[1] + s.size[1]));
      const d = Math.hypot(dx, dy);
      if (d < bd) {
        bd = d;
        best = s;
      }
    }
    const a = Math.min(best.size[0], Math.max(0, X - best.at[0])) + best.min[0];
    const c = Math.min(best.size[1], Math.max(0, Y - best.at[1])) + best.min[1];
    // Sides measure courses from the bottom rim (z = −0.5) so they meet round the corners.
    return best.n[2] === 0 ? bricks(a + 4, c + 0.5, false) : bricks(a + 4, c + 4, true);
  });
  return {
    name: 'brick-box',
    cage,
    map,
    scale: 0.045,
    midLevel: 0.5,
    wrap: 'clamp',
    desc: 'brick box: the creased box with a box unwrap (6 uv islands, every box edge a UV seam) and an 8-bit 512x256 brick height map',
  };
}

/**
 * Wrinkled creature: the creature cage with a cylindrical projection round the body's long
 * (x) axis, u along x, v the angle; faces that straddle the angle's wrap get v + 1 on their
 * low corners (a UV seam whose two sides address the same texels under repeat wrapping),
 * and a 16-bit 256 x 256 periodic fractal value-noise map (tiles in u and v).
 */
function creatureNoise(): DisplacedModel {
  const b = creature();
  const cage0 = b.cage();
  let xmin = Infinity,
    xmax = -Infinity;
  for (const p of b.v) {
    xmin = Math.min(xmin, p[0]);
    xmax = Math.max(xmax, p[0]);
  }
  const zc = 1.2;
  const ang = (p: V3): number => Math.atan2(p[2] - zc, p[1]) / (2 * Math.PI) + 0.5;
  const cage = withCornerUvs(cage0, (f, j) => {
    const vs = b.f[f].map((i) => ang(b.v[i]));
    const wraps = Math.max(...vs) - Math.min(...vs) > 0.5;
    const p = b.v[b.f[f][j]];
    const v = vs[j] + (wraps && vs[j] < 0.5 ? 1 : 0);
    return [(p[0] - xmin) / (xmax - xmin), v];
  });
  const lattice = (u: number, v: number, n: number, m: number, oct: number): number => {
    const x = u * n,
      y = v * m,
      i = Math.floor(x),
      j = Math.floor(y);
    const fx = smoothstep(0, 1, x - i),
      fy = smoothstep(0, 1, y - j);
    const g = (a: number, c: number): number => hash01(((a % n) + n) % n, ((c % m) + m) % m, oct);
    return (1 - fy) * ((1 - fx) * g(i, j) + fx * g(i + 1, j)) + fy * ((1 - fx) * g(i, j + 1) + fx * g(i + 1, j + 1));
  };
  const map = heightMapFromFunction(256, 256, 16, (u, v) => {
    let s = 0,
      amp = 0.5,
      total = 0;
    for (let o = 0; o < 4; o++) {
      s += amp * lattice(u, v, 12 << o, 8 << o, o);
      total += amp;
      amp *= 0.5;
    }
    return s / total;
  });
  return {
    name: 'creature-wrinkles',
    cage,
    map,
    scale: 0.12,
    midLevel: 0.5,
    wrap: 'repeat',
    desc: 'the creature with a cylindrical uv projection (a seam where the angle wraps) and a 16-bit 256x256 tiling fractal-noise height map',
  };
}

const MODELS: [string, () => Builder, string][] = [
  ['creased-box', creasedBox, 'creased box: semi-sharp (2.5) top rim, infinitely sharp bottom rim, a 1.5 vertical edge, a sharp corner'],
  ['torus', torus, 'torus 16x8: every vertex valence 4, all patches regular'],
  ['pawn', pawn, 'chess pawn by revolution (16 segments): n-gon base, triangle-fan top, rims as creases'],
  ['gear', gear, 'gear with 10 teeth: 7-gons, triangles, valence 3/4/5/6 vertices, creased rims, axle hole'],
  ['icosphere', icosphere, 'icosphere (icosahedron split once) with one pentagonal cap: mostly triangles'],
  ['sheet', sheet, 'open wavy sheet with a boundary, an infinitely sharp fold and a semi-sharp ridge'],
  ['creature', creature, 'box-modelled creature: extruded legs, neck, head, tail; ears and eyes poked into triangles'],
];

/**
 * The models are built Z-up (their builders think in x, y on the ground and z up) and stored Y-up,
 * OBJ's convention and the world's: (x, y, z) → (x, z, −y), a rotation about x (no mirroring, so
 * faces stay counter-clockwise from outside), exact in floating point (a swap and a negation).
 * A user's model opened in the demo is read Y-up unless they choose Z; the project's own then
 * need no turning, and the CLI's views see them as the demo does.
 */
function storedYUp(cage: Cage): Cage {
  return turnUpAxis(cage, 'y-up');
}

const outDir = process.argv[2] ?? 'public/models';
mkdirSync(outDir, { recursive: true });
for (const [name, make, desc] of MODELS) {
  const cage = storedYUp(make().cage());
  const text = writeObj(
    cage,
    `tessellab model "${name}": ${desc}\nGenerated by scripts/models.ts (npm run models). Licence: MIT, as the repository.`,
  );
  const { topology: T } = loadCage(text); // validates
  const sizes = new Map<number, number>();
  for (let f = 0; f < T.nFaces; f++) {
    const n = T.faceOffsets[f + 1] - T.faceOffsets[f];
    sizes.set(n, (sizes.get(n) ?? 0) + 1);
  }
  const val = new Set<number>();
  for (let v = 0; v < T.nVerts; v++) val.add(T.valence[v]);
  writeFileSync(`${outDir}/${name}.obj`, text);
  console.log(
    `${name}.obj: ${T.nVerts} v, ${T.nFaces} f, sizes ${[...sizes]
      .sort()
      .map(([k, c]) => `${k}:${c}`)
      .join(' ')}, valences ${[...val].sort((a, z) => a - z).join(',')}, creases ${cage.creases.length}, corners ${cage.corners.length}`,
  );
}

// Displaced models: OBJ with vt, the height map PNG, and their displacement parameters in
// displaced.json (read by the demo and the CLI; h = (sample − midLevel)·scale, wrap as heightmap.ts).
const displacedList: object[] = [];
for (const m of [brickBox(), creatureNoise()]) {
  const text = writeObj(
    storedYUp(m.cage),
    `tessellab model "${m.name}": ${m.desc}\nHeight map ${m.name}-height.png: h = (sample - ${m.midLevel}) * ${m.scale} along the limit normal, ${m.wrap} wrap.\nGenerated by scripts/models.ts (npm run models). Licence: MIT, as the repository.`,
  );
  const { cage, topology: T } = loadCage(text); // validates, and the uvs must survive the round trip
  if (uvCoverage(cage) !== 'complete') throw new Error(`${m.name}: uvs lost`);
  const seams = uvSeams(cage, T).edge.reduce((a, x) => a + x, 0);
  const png = encodeHeightPng(m.map);
  writeFileSync(`${outDir}/${m.name}.obj`, text);
  writeFileSync(`${outDir}/${m.name}-height.png`, png);
  displacedList.push({
    model: `${m.name}.obj`,
    heightMap: `${m.name}-height.png`,
    bits: m.map.bits,
    scale: m.scale,
    midLevel: m.midLevel,
    wrap: m.wrap,
  });
  console.log(
    `${m.name}.obj: ${T.nVerts} v, ${T.nFaces} f, ${cage.uvs.length / 2} vt, ${seams} seam edges; ${m.name}-height.png: ${m.map.width}x${m.map.height} ${m.map.bits}-bit, ${png.length} B`,
  );
}
writeFileSync(`${outDir}/displaced.json`, JSON.stringify(displacedList, null, 2) + '\n');
