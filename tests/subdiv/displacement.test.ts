// CPU reference of the displaced limit surface (src/subdiv/displace.ts): P' = P + h(uv)·N with
// the displaced normal from the height map's gradient and the limit tangents.
// Stated bounds (measured values in the comments of each test):
//  - flat cage (no curvature, so the dropped h·∂N/∂u term is zero): the normal agrees with
//    central finite differences of P' (step 1e-6) within 1e-6 rad;
//    (measured 1.9e-10 rad, with the map tilting the normal by up to 0.46 rad);
//  - torus (curved): without the h·∂N term the angle to finite differences is below
//    max|h|·κmax (κmax = 1/r = 2.5, the tube curvature; 0.054 rad for max|h| = 0.021; measured
//    2.8e-3 rad = 0.16°); with the term added back from finite differences of N (test only) it
//    closes to 1e-6 rad (measured 7e-10), so the rest of the formula is exact.
import { describe, expect, it } from 'vitest';
import { type Cage, loadCage, makeCage } from '../../src/mesh/index.ts';
import { type HeightMap, heightMapFromFunction, makeHeightMap, sampleHeight } from '../../src/mesh/heightmap.ts';
import { DisplacedSurface, type SurfaceParam, Surface, faceEdgeParam, weldOwnerFaces } from '../../src/subdiv/index.ts';
import { prepareMesh } from '../../src/gpu/tess/prepare.ts';
import { OWNER_WORD } from '../../src/gpu/contract/tess.ts';
import { readFileSync } from 'node:fs';

type V3 = [number, number, number];
const sub = (a: V3, b: V3): V3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const crs = (a: V3, b: V3): V3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const unit = (a: V3): V3 => {
  const l = Math.hypot(...a);
  return [a[0] / l, a[1] / l, a[2] / l];
};
const angle = (a: V3, b: V3): number => Math.atan2(Math.hypot(...crs(a, b)), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);

/** A cage with per-corner uvs given as one [u, v] per face corner (face-varying, no sharing). */
function withUvs(cage: Cage, cornerUvs: [number, number][]): Cage {
  return { ...cage, uvs: Float64Array.from(cornerUvs.flat()), faceUvIndices: Int32Array.from(cornerUvs.map((_, i) => i)) };
}

/** n x n grid of quads on z = 0, uv = (x, y) / n (one shared chart, no seams). */
function flatGrid(n = 4): Cage {
  const pos: number[] = [],
    faces: number[][] = [],
    uvs: [number, number][] = [];
  for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) pos.push(i, j, 0);
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++) {
      const f = [j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i];
      faces.push(f);
      for (const v of f) uvs.push([(v % (n + 1)) / n, Math.floor(v / (n + 1)) / n]);
    }
  return withUvs(makeCage(pos, faces), uvs);
}

/** Torus nu x nv (R = 1, r = 0.4) with uv = (i/nu, j/nv); the last column and row use u = 1, v = 1 (a value seam). */
function torusUv(nu = 16, nv = 8, r = 0.4): Cage {
  const pos: number[] = [],
    faces: number[][] = [],
    uvs: [number, number][] = [];
  for (let j = 0; j < nv; j++)
    for (let i = 0; i < nu; i++) {
      const a = (2 * Math.PI * i) / nu,
        t = (2 * Math.PI * j) / nv;
      pos.push((1 + r * Math.cos(t)) * Math.cos(a), (1 + r * Math.cos(t)) * Math.sin(a), r * Math.sin(t));
    }
  const id = (i: number, j: number): number => (j % nv) * nu + (i % nu);
  for (let j = 0; j < nv; j++)
    for (let i = 0; i < nu; i++) {
      faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
      uvs.push([i / nu, j / nv], [(i + 1) / nu, j / nv], [(i + 1) / nu, (j + 1) / nv], [i / nu, (j + 1) / nv]);
    }
  return withUvs(makeCage(pos, faces), uvs);
}

const smooth16: HeightMap = heightMapFromFunction(
  64,
  64,
  16,
  (u, v) => 0.5 + 0.3 * Math.sin(2 * Math.PI * (3 * u + v)) * Math.cos(2 * Math.PI * 2 * v) + 0.15 * Math.sin(2 * Math.PI * 5 * u),
);

/**
 * A map whose texels are exactly a bilinear function of their indices (integers, so no rounding):
 * there the map's gradient (its texels' central differences, blended: src/mesh/heightmap.ts) is
 * the value's own derivative, away from the map's border, and finite differences of P' can
 * check the displaced normal's formula exactly. On other maps the gradient is smoothed: the
 * normal is not the bilinear surface's, by design.
 */
function bilinearMap(W: number, H: number): HeightMap {
  const data = new Uint16Array(W * H);
  const a = 28000 / W,
    b = 20000 / H,
    c = 16000 / (W * H);
  for (let j = 0; j < H; j++)
    for (let i = 0; i < W; i++) data[j * W + i] = 1000 + Math.round(a) * i + Math.round(b) * j + Math.round(c) * i * j;
  return makeHeightMap(W, H, data, 16);
}
const bilinear16 = bilinearMap(64, 64);

/** Deterministic points well inside texel cells (so central differences do not straddle a bilinear
 * kink) and, on bilinear16, more than a texel from the map's border (where the wrap breaks the
 * bilinear function). */
function samplePoints(ds: DisplacedSurface, count: number, seed = 1): { face: number; u: number; v: number }[] {
  let x = seed;
  const rnd = (): number => {
    x = (x * 1103515245 + 12345) % 2147483648;
    return x / 2147483648;
  };
  const out: { face: number; u: number; v: number }[] = [];
  const { width: W, height: H } = ds.map;
  while (out.length < count) {
    const p = { face: Math.floor(rnd() * ds.surface.faceCount), u: 0.05 + 0.9 * rnd(), v: 0.05 + 0.9 * rnd() };
    const uv = ds.evaluateLocal(p).uv;
    const fx = uv[0] * W - 0.5,
      fy = (1 - uv[1]) * H - 0.5;
    const frac = (z: number): number => z - Math.floor(z);
    const inside = ds.map !== bilinear16 || (fx > 1.5 && fx < W - 2.5 && fy > 1.5 && fy < H - 2.5);
    if (inside && Math.min(frac(fx), 1 - frac(fx), frac(fy), 1 - frac(fy)) > 0.02) out.push(p);
  }
  return out;
}

/** Central differences of P' (and of the base N) at a quad point. */
function finiteDiff(ds: DisplacedSurface, p: { face: number; u: number; v: number }, d = 1e-6) {
  const P = (u: number, v: number): V3 => ds.evaluateLocal({ face: p.face, u, v }).P;
  const N = (u: number, v: number): V3 => ds.evaluateLocal({ face: p.face, u, v }).base.N;
  const s = 1 / (2 * d);
  const Pu = sub(P(p.u + d, p.v), P(p.u - d, p.v)).map((c) => c * s) as V3;
  const Pv = sub(P(p.u, p.v + d), P(p.u, p.v - d)).map((c) => c * s) as V3;
  const Nu = sub(N(p.u + d, p.v), N(p.u - d, p.v)).map((c) => c * s) as V3;
  const Nv = sub(N(p.u, p.v + d), N(p.u, p.v - d)).map((c) => c * s) as V3;
  return { Pu, Pv, Nu, Nv, normal: unit(crs(Pu, Pv)) };
}

describe('displaced limit surface (CPU reference)', () => {
  it('h = 0 (scale 0) is the plain limit surface; a constant map is a pure offset along the normal', () => {
    const cage = torusUv();
    const surface = new Surface(cage);
    const zero = new DisplacedSurface(surface, smooth16, { scale: 0, midLevel: 0.5 });
    const c = makeHeightMap(2, 2, Uint16Array.from([200, 200, 200, 200]), 8);
    const flat = new DisplacedSurface(surface, c, { scale: 0.3, midLevel: 0.25 });
    const off = (200 / 255 - 0.25) * 0.3;
    for (const p of samplePoints(zero, 40)) {
      const a = zero.evaluateLocal(p);
      expect(Math.abs(a.h)).toBe(0);
      expect(a.P).toEqual(a.base.P);
      expect(angle(a.N, a.base.N)).toBeLessThan(1e-12);
      const b = flat.evaluateLocal(p);
      expect(b.h).toBeCloseTo(off, 15);
      expect(Math.abs(b.dhdu)).toBe(0);
      expect(Math.abs(b.dhdv)).toBe(0);
      for (let k = 0; k < 3; k++) expect(Math.abs(b.P[k] - (b.base.P[k] + off * b.base.N[k]))).toBeLessThan(1e-15);
      expect(angle(b.N, b.base.N)).toBeLessThan(1e-12);
    }
  });

  it("flat cage: the displaced normal matches finite differences of P' within 1e-6 rad", () => {
    const ds = new DisplacedSurface(new Surface(flatGrid()), bilinear16, { scale: 2, midLevel: 0.5 });
    let worst = 0,
      tilt = 0;
    for (const p of samplePoints(ds, 60, 7)) {
      const a = ds.evaluateLocal(p);
      const fd = finiteDiff(ds, p);
      worst = Math.max(worst, angle(a.N, fd.normal));
      tilt = Math.max(tilt, angle(a.N, a.base.N));
    }
    expect(worst).toBeLessThan(1e-6);
    expect(tilt).toBeGreaterThan(0.3); // the map really tilts the normal (else the test proves nothing)
  });

  it('torus: within max|h|·κ of finite differences without the h·∂N term, within 1e-6 rad with it', () => {
    const scale = 0.05,
      mid = 0.5;
    const ds = new DisplacedSurface(new Surface(torusUv()), bilinear16, { scale, midLevel: mid });
    let worst = 0,
      worstFixed = 0,
      maxH = 0;
    for (const p of samplePoints(ds, 60, 3)) {
      const a = ds.evaluateLocal(p);
      const fd = finiteDiff(ds, p);
      worst = Math.max(worst, angle(a.N, fd.normal));
      maxH = Math.max(maxH, Math.abs(a.h));
      // Add back the dropped term: ∂P'/∂u = ∂P/∂u + ∂h/∂u·N + h·∂N/∂u.
      const Pu: V3 = [0, 0, 0],
        Pv: V3 = [0, 0, 0];
      for (let k = 0; k < 3; k++) {
        Pu[k] = a.base.dPdu[k] + a.dhdu * a.base.N[k] + a.h * fd.Nu[k];
        Pv[k] = a.base.dPdv[k] + a.dhdv * a.base.N[k] + a.h * fd.Nv[k];
      }
      worstFixed = Math.max(worstFixed, angle(unit(crs(Pu, Pv)), fd.normal));
    }
    // The dropped term h·∂N/∂u is tangential, so it moves the normal only through its product
    // with the height slope: the angle is at most about |h|·κ·tan(tilt) < |h|·κ.
    const bound = maxH * (1 / 0.4);
    expect(worst).toBeLessThan(bound);
    expect(worst).toBeGreaterThan(worstFixed); // the dropped term is what the gap is
    expect(worstFixed).toBeLessThan(1e-6);
  });

  it('n-gon sub-faces: uv, height and normal use the (k, s, t) parameterisation consistently', () => {
    // Pentagonal prism, every face its own uv island (regular pentagon / unit square).
    const { cage, ds } = prism(bilinear16);
    const top = 0; // face 0 is the top pentagon
    const d = 1e-6;
    let worstFixed = 0,
      tilt = 0;
    for (const [k, s, t] of [
      [0, 0.3, 0.4],
      [2, 0.7, 0.2],
      [4, 0.55, 0.8],
      [1, 0.15, 0.6],
    ]) {
      const a = ds.evaluateLocal({ face: top, k, s, t });
      const at = (ss: number, tt: number) => ds.evaluateLocal({ face: top, k, s: ss, t: tt });
      const dP = (f: (q: ReturnType<typeof at>) => V3) => [
        sub(f(at(s + d, t)), f(at(s - d, t))).map((c) => c / (2 * d)) as V3,
        sub(f(at(s, t + d)), f(at(s, t - d))).map((c) => c / (2 * d)) as V3,
      ];
      const [Ps, Pt] = dP((q) => q.P),
        [Ns, Nt] = dP((q) => q.base.N);
      const fdNormal = unit(crs(Ps, Pt));
      const Pu: V3 = [0, 0, 0],
        Pv: V3 = [0, 0, 0];
      for (let c = 0; c < 3; c++) {
        Pu[c] = a.base.dPdu[c] + a.dhdu * a.base.N[c] + a.h * Ns[c];
        Pv[c] = a.base.dPdv[c] + a.dhdv * a.base.N[c] + a.h * Nt[c];
      }
      worstFixed = Math.max(worstFixed, angle(unit(crs(Pu, Pv)), fdNormal));
      expect(angle(a.N, fdNormal)).toBeLessThan(Math.abs(a.h) * 10); // the dropped term: |h|·κ, κ < 10 on this prism's top
      tilt = Math.max(tilt, angle(a.N, a.base.N));
      expect(a.normalExact).toBe(true);
    }
    expect(worstFixed).toBeLessThan(1e-6);
    expect(tilt).toBeGreaterThan(0.02);
    expect(cage.faceOffsets[1] - cage.faceOffsets[0]).toBe(5);
  });
});

/** Pentagonal prism: top 5-gon (face 0), bottom 5-gon (face 1), five side quads; each face its own uv island. */
function prism(heights?: HeightMap): { cage: Cage; ds: DisplacedSurface } {
  const pos: number[] = [];
  for (const z of [0, 1]) for (let k = 0; k < 5; k++) pos.push(Math.cos((2 * Math.PI * k) / 5), Math.sin((2 * Math.PI * k) / 5), z);
  const faces = [
    [5, 6, 7, 8, 9],
    [4, 3, 2, 1, 0],
  ];
  for (let k = 0; k < 5; k++) faces.push([k, (k + 1) % 5, 5 + ((k + 1) % 5), 5 + k]);
  const uvs: [number, number][] = [];
  for (const f of faces) {
    if (f.length === 5)
      for (let k = 0; k < 5; k++) uvs.push([0.5 + 0.45 * Math.cos((2 * Math.PI * k) / 5), 0.5 + 0.45 * Math.sin((2 * Math.PI * k) / 5)]);
    else uvs.push([0, 0], [1, 0], [1, 1], [0, 1]);
  }
  const cage = withUvs(makeCage(pos, faces), uvs);
  // An asymmetric map, so the two sides of a seam really disagree.
  const map = heightMapFromFunction(32, 32, 8, (u, v) => 0.5 + 0.4 * Math.sin(7 * u + 2) * Math.cos(5 * v - 1));
  return { cage, ds: new DisplacedSurface(new Surface(cage), heights ?? map, { scale: 0.04, midLevel: 0.5 }) };
}

describe('UV seams: one owner per weld vertex', () => {
  it('every cage edge and vertex of a cage where every edge is a seam displaces identically from all its faces', () => {
    const { cage, ds } = prism();
    const T = ds.surface.topology;
    let disagreeLocal = 0,
      checked = 0;
    for (let h = 0; h < T.faceIndices.length; h++) {
      const tw = T.heTwin[h];
      if (tw < h) continue; // each interior edge once (closed cage: every edge has a twin)
      const a = T.faceIndices[h],
        b = T.faceIndices[T.heNext[h]];
      const lo = Math.min(a, b);
      for (const x of [0.125, 0.25, 0.5, 0.625, 0.875]) {
        const sides: SurfaceParam[] = [h, tw].map((hh) => {
          const f = T.heFace[hh],
            j = hh - T.faceOffsets[f];
          return faceEdgeParam(cage, f, j, T.faceIndices[hh] === lo ? x : 1 - x);
        });
        const [pa, pb] = sides.map((p) => ds.at(p));
        expect(pa.P).toEqual(pb.P);
        expect(pa.N).toEqual(pb.N);
        expect(pa.at.face).toBe(Math.min(T.heFace[h], T.heFace[tw])); // lowest face id owns the edge
        expect(pa.P).toEqual(ds.edgePoint(a, b, x).P);
        // The two faces' own surfaces meet (same limit point) but their heights differ: a real seam.
        const [la, lb] = sides.map((p) => ds.evaluateLocal(p));
        for (let k = 0; k < 3; k++) expect(Math.abs(la.base.P[k] - lb.base.P[k])).toBeLessThan(1e-12);
        if (Math.abs(la.h - lb.h) > 1e-4) disagreeLocal++;
        checked++;
      }
    }
    expect(checked).toBe(15 * 5);
    expect(disagreeLocal).toBeGreaterThan(checked / 2);
    // Corners: every face around a vertex gets the owner's result.
    for (let v = 0; v < T.nVerts; v++) {
      const got = [];
      for (let k = T.vertHeOffsets[v]; k < T.vertHeOffsets[v + 1]; k++) {
        const hh = T.vertHe[k],
          f = T.heFace[hh];
        got.push(ds.at(faceEdgeParam(cage, f, hh - T.faceOffsets[f], 0)));
      }
      expect(got.length).toBe(3);
      for (const g of got) {
        expect(g.P).toEqual(got[0].P);
        expect(g.N).toEqual(got[0].N);
        expect(g.at.face).toBe(ds.vertexOwner[v]);
      }
    }
  });

  it("the owners are the faces through which the compute tessellator's weld evaluates (prepare.ts)", () => {
    const models = ['creature', 'pawn', 'gear', 'icosphere', 'creased-box', 'sheet'];
    for (const name of models) {
      const { cage, topology: T } = loadCage(readFileSync(new URL(`../../public/models/${name}.obj`, import.meta.url), 'utf8'));
      const own = weldOwnerFaces(T, (f) => !cage.holes.includes(f));
      const mesh = prepareMesh(cage);
      for (let v = 0; v < T.nVerts; v++) {
        const o = mesh.vertexOwner[v];
        expect(own.vertex[v]).toBe(o === 0xffffffff ? -1 : mesh.triFace[o >>> 2]);
      }
      const prepEdge = new Map<string, number>();
      for (let e = 0; e < mesh.edgeCount; e++)
        prepEdge.set(`${mesh.edgeVerts[2 * e]},${mesh.edgeVerts[2 * e + 1]}`, mesh.triFace[OWNER_WORD.get(mesh.edgeOwner[e], 'tri')]);
      for (let e = 0; e < T.nEdges; e++) {
        const a = T.edgeVerts[2 * e],
          b = T.edgeVerts[2 * e + 1];
        expect(own.edge[e], `${name} edge ${a}-${b}`).toBe(prepEdge.get(`${Math.min(a, b)},${Math.max(a, b)}`));
      }
    }
  });

  it('a torus seam where both sides address the same texels (repeat wrap) is continuous even without the rule', () => {
    const ds = new DisplacedSurface(new Surface(torusUv()), smooth16, { scale: 0.05, midLevel: 0.5 });
    // Face 15 (i = 15) ends at u = 1; face 0 starts at u = 0 on the same cage edge.
    for (const v of [0.25, 0.5, 0.75]) {
      const a = ds.evaluateLocal({ face: 15, u: 1, v }),
        b = ds.evaluateLocal({ face: 0, u: 0, v });
      expect(a.uv[0]).toBe(1);
      expect(b.uv[0]).toBe(0);
      expect(Math.abs(a.h - b.h)).toBeLessThan(1e-12);
      expect(sampleHeight(smooth16, 1, a.uv[1]).value).toBeCloseTo(sampleHeight(smooth16, 0, a.uv[1]).value, 12);
    }
  });
});

describe("the project's displaced models (public/models/displaced.json)", () => {
  const list = JSON.parse(readFileSync(new URL('../../public/models/displaced.json', import.meta.url), 'utf8')) as {
    model: string;
    heightMap: string;
    bits: 8 | 16;
    scale: number;
    midLevel: number;
    wrap: 'repeat' | 'clamp';
  }[];

  it('lists at least two models, each with complete UVs, real seams and a decodable map', async () => {
    const { decodeHeightPng } = await import('../../src/mesh/heightmap-png.ts');
    const { uvCoverage, uvSeams } = await import('../../src/mesh/index.ts');
    expect(list.length).toBeGreaterThanOrEqual(2);
    for (const m of list) {
      const { cage, topology } = loadCage(readFileSync(new URL(`../../public/models/${m.model}`, import.meta.url), 'utf8'));
      expect(uvCoverage(cage)).toBe('complete');
      expect(uvSeams(cage, topology).edge.some((x) => x === 1)).toBe(true);
      const bytes = readFileSync(new URL(`../../public/models/${m.heightMap}`, import.meta.url));
      expect(bytes.length).toBeLessThan(300_000);
      const map = decodeHeightPng(new Uint8Array(bytes));
      expect(map.bits).toBe(m.bits);
      // The map is not flat: it has detail to displace.
      let lo = Infinity,
        hi = -Infinity;
      for (const x of map.data) {
        lo = Math.min(lo, x);
        hi = Math.max(hi, x);
      }
      expect((hi - lo) / ((1 << map.bits) - 1)).toBeGreaterThan(0.4);
    }
  });

  it('displace without NaN, within their height range, and identically from both sides of every cage edge', async () => {
    const { decodeHeightPng } = await import('../../src/mesh/heightmap-png.ts');
    for (const m of list) {
      const { cage, topology: T } = loadCage(readFileSync(new URL(`../../public/models/${m.model}`, import.meta.url), 'utf8'));
      const map = decodeHeightPng(new Uint8Array(readFileSync(new URL(`../../public/models/${m.heightMap}`, import.meta.url))));
      const ds = new DisplacedSurface(new Surface(cage, T), map, m);
      const hmax = m.scale * Math.max(m.midLevel, 1 - m.midLevel);
      let moved = 0;
      for (let f = 0; f < T.nFaces; f += 3) {
        if (T.faceOffsets[f + 1] - T.faceOffsets[f] !== 4) continue;
        for (const [u, v] of [
          [0.3, 0.6],
          [0.5, 0.5],
          [0.8, 0.1],
        ]) {
          const p = ds.at({ face: f, u, v });
          for (const c of [...p.P, ...p.N]) expect(Number.isFinite(c)).toBe(true);
          expect(Math.abs(p.h)).toBeLessThanOrEqual(hmax + 1e-12);
          if (Math.abs(p.h) > 0.1 * hmax) moved++;
        }
      }
      expect(moved).toBeGreaterThan(10);
      for (let h = 0; h < T.faceIndices.length; h += 5) {
        const tw = T.heTwin[h];
        if (tw < 0) continue;
        const lo = Math.min(T.faceIndices[h], T.faceIndices[tw]);
        const [pa, pb] = [h, tw].map((hh) => {
          const f = T.heFace[hh];
          return ds.at(faceEdgeParam(cage, f, hh - T.faceOffsets[f], T.faceIndices[hh] === lo ? 0.375 : 0.625));
        });
        expect(pa.P).toEqual(pb.P);
      }
    }
  });
});

describe('per-face data for the GPU and the factor rule', () => {
  it('faceSampleRange contains every sample in the face and is tight on a gradient map', async () => {
    const { faceSampleRange } = await import('../../src/mesh/index.ts');
    const { decodeHeightPng } = await import('../../src/mesh/heightmap-png.ts');
    const list = JSON.parse(readFileSync(new URL('../../public/models/displaced.json', import.meta.url), 'utf8')) as {
      model: string;
      heightMap: string;
      scale: number;
      midLevel: number;
      wrap: 'repeat' | 'clamp';
    }[];
    for (const m of list) {
      const { cage, topology: T } = loadCage(readFileSync(new URL(`../../public/models/${m.model}`, import.meta.url), 'utf8'));
      const map = decodeHeightPng(new Uint8Array(readFileSync(new URL(`../../public/models/${m.heightMap}`, import.meta.url))));
      const ds = new DisplacedSurface(new Surface(cage, T), map, m);
      const range = faceSampleRange(cage, map, m.wrap);
      for (let f = 0; f < T.nFaces; f += 7) {
        const n = T.faceOffsets[f + 1] - T.faceOffsets[f];
        for (const [s, t] of [
          [0, 0],
          [0.5, 0.5],
          [0.9, 0.2],
          [1, 1],
          [0.33, 0.77],
        ]) {
          const p = ds.evaluateLocal(n === 4 ? { face: f, u: s, v: t } : { face: f, k: 1, s, t });
          const sample = p.h / m.scale + m.midLevel;
          expect(sample).toBeGreaterThanOrEqual(range[2 * f] - 1e-12);
          expect(sample).toBeLessThanOrEqual(range[2 * f + 1] + 1e-12);
        }
      }
    }
    // A ramp in u over a 4 x 4 grid: each column of faces sees only its quarter of the ramp (plus one texel).
    const grid = flatGrid(4);
    const ramp = heightMapFromFunction(64, 8, 16, (u) => u);
    const r = faceSampleRange(grid, ramp, 'clamp');
    for (let f = 0; f < 16; f++) {
      const col = f % 4;
      // Texel centres sit at (i + ½)/64 (16-bit quantised): the range reaches half a texel past the face on each side.
      expect(r[2 * f]).toBeLessThanOrEqual(col / 4 + 0.5 / 64 + 1 / 65535);
      expect(r[2 * f + 1]).toBeGreaterThanOrEqual((col + 1) / 4 - 0.5 / 64 - 1 / 65535);
      expect(r[2 * f + 1] - r[2 * f]).toBeLessThanOrEqual(0.25 + 2 / 64 + 2 / 65535);
    }
  });

  it("faceCornerUvs packs each corner's uv at its face-corner offset", async () => {
    const { faceCornerUvs, uvAtSubFace } = await import('../../src/mesh/index.ts');
    const { cage } = prism();
    const packed = faceCornerUvs(cage);
    expect(packed.length).toBe(2 * cage.faceIndices.length);
    for (let f = 0; f < 7; f++) {
      const n = cage.faceOffsets[f + 1] - cage.faceOffsets[f];
      for (let j = 0; j < n; j++) {
        const uv = n === 4 ? uvAtSubFace(cage, f, 0, [0, 1, 1, 0][j], [0, 0, 1, 1][j]).uv : uvAtSubFace(cage, f, j, 0, 0).uv;
        expect(packed[2 * (cage.faceOffsets[f] + j)]).toBe(Math.fround(uv[0]));
        expect(packed[2 * (cage.faceOffsets[f] + j) + 1]).toBe(Math.fround(uv[1]));
      }
    }
    expect(() => faceCornerUvs(makeCage([0, 0, 0, 1, 0, 0, 0, 1, 0], [[0, 1, 2]]))).toThrow(/texture coordinate/);
  });
});
