/**
 * The fans of the Catmull-Clark preparation (part 2 of the header of src/gpu/cc/build.ts): which
 * vertices are fan centres, each fan's sectors and radial blend exponent, the limit rule of every
 * prepared vertex, and the packing of the fans into the point space (slices and limits), the fan,
 * sector and cos words, and the slice kernel's workgroups.
 */
import { type HalfEdges, SHARPNESS_INFINITE, decSharp, vertexRing } from '../../mesh/index.ts';
import type { PreparedMesh } from '../tess/prepare.ts';
import { CC_NONE } from '../contract/cc.ts';
import { NO_OWNER, OWNER_WORD } from '../contract/tess.ts';
import { WORKGROUP_SIZE } from '../contract/constants.ts';
import {
  CC_AXIS_INFINITE,
  CC_FAN_WORD,
  CC_MAX_FAN_SECTORS,
  CC_PAIR_WORD,
  CC_STEP_RULE_WORD,
  CC_THREAD_WORD,
  CC_VERTEX_LIMIT_WORD,
  CC_WIDE_FAN,
} from './words.ts';
import { U32, f32bits } from './word-list.ts';
import {
  type Level,
  type LevelStack,
  MAX_LEVEL,
  VRULE_CREASE,
  VRULE_SMOOTH,
  type VertexStep,
  isQuadHe,
  isRegular,
  vertexRuleOf,
  vertexStep,
} from './levels.ts';
import { creaseVertexGrid } from './single-crease.ts';

const INF = SHARPNESS_INFINITE;

/**
 * Depth of the fans: a fan starting at level s has TOTAL_DEPTH − s steps, so the blended square
 * round an EV is 2^-8 of a quad's (u, v) and 2^-7 of an n-gon sub-face's (s, t). The finest
 * spacing of an integer tess factor (64) is 1/64 of a quad's edge (1/32 of (s, t) =
 * 2·barycentric), but fractional factors make thinner slivers next to a corner, and the checks
 * hold every output vertex, blended or not, to 1e-5 of the diagonal: at 2^-6 the radial blend
 * missed that by ×1.3 (icosphere, creature), at 2^-8 it is under 2e-6. (Each step costs a
 * centre and, every other step, 2 points per sector: 12 B per sector per step on average.)
 */
export const TOTAL_DEPTH = 8;
/** Extra fan depth round creases, corners, darts and boundary vertices (see the packing). */
const EXTRA_DEPTH_SHARP = 3;

const sharp0orInf = (s: number) => s === 0 || s >= INF;

/** Is x a fan centre at this level (see the header of src/gpu/cc/build.ts: the slice kernel is exact round it)? */
function isEligible(L: Level, x: number): boolean {
  if (L.eligible[x] >= 0) return L.eligible[x] === 1;
  const r = eligible(L, x);
  L.eligible[x] = r ? 1 : 0;
  return r;
}

const isSemi = (s: number) => s > 0 && s < INF;

/** Is y a valid axis neighbour (1,0) of a fan centre along an axis of sharpness axisSharp? Along
 * a semi-sharp axis (uniform creasing only) y is an interior valence-4 vertex whose only sharp
 * edges are the two halves of the axis, opposite in its ring and of one sharpness: the crease
 * runs straight through y, so every step makes the same kind of point there, one sharpness lower. */
function axisOk(L: Level, y: number, axisSharp: number): boolean {
  const m = L.he;
  if (L.vertSharp[y] !== 0) return false;
  const nf = m.vertHeOffsets[y + 1] - m.vertHeOffsets[y],
    ne = m.vertEdgeOffsets[y + 1] - m.vertEdgeOffsets[y];
  for (let k = m.vertHeOffsets[y]; k < m.vertHeOffsets[y + 1]; k++) if (!isQuadHe(m, m.vertHe[k])) return false;
  if (isSemi(axisSharp)) {
    if (L.chaikin || L.boundary[y] || nf !== 4 || ne !== 4) return false;
    // Exactly two sharp edges, both of the axis's σ, and no face between them (opposite).
    let a = -1,
      b = -1;
    for (let k = m.vertEdgeOffsets[y]; k < m.vertEdgeOffsets[y + 1]; k++) {
      const e = m.vertEdges[k];
      const s = L.edgeSharp[e];
      if (s === 0) continue;
      if (s !== axisSharp || b >= 0) return false;
      if (a < 0) a = e;
      else b = e;
    }
    if (b < 0) return false;
    for (let k = m.vertHeOffsets[y]; k < m.vertHeOffsets[y + 1]; k++) {
      const h = m.vertHe[k];
      const e0 = m.heEdge[h],
        e1 = m.heEdge[m.hePrev[h]];
      if ((e0 === a && e1 === b) || (e0 === b && e1 === a)) return false;
    }
    return true;
  }
  let nInf = 0;
  for (let k = m.vertEdgeOffsets[y]; k < m.vertEdgeOffsets[y + 1]; k++) {
    const s = L.edgeSharp[m.vertEdges[k]];
    if (s >= INF) nInf++;
    else if (s !== 0) return false;
  }
  if (L.boundary[y]) return axisSharp >= INF && nf === 2 && ne === 3 && nInf === 2 && isRegular(L, y);
  if (nf !== 4 || ne !== 4) return false;
  if (axisSharp >= INF) return nInf === 2 && isRegular(L, y); // the two halves of the axis, opposite
  return nInf === 0;
}

function eligible(L: Level, x: number): boolean {
  const m = L.he;
  // Semi-sharp edges at the centre, and its own semi-sharp sharpness, decay inside the slice
  // kernel (uniform creasing; the centre's rule per step from packFans' table), so a fan takes
  // them at once, unless x is a cage vertex on a straight crease (single-crease patches round it
  // and its closed-form limit, no slices: vertexLimits).
  let semi = isSemi(L.vertSharp[x]);
  for (let k = m.vertEdgeOffsets[x]; k < m.vertEdgeOffsets[x + 1]; k++) {
    const s = L.edgeSharp[m.vertEdges[k]];
    if (isSemi(s)) semi = true;
    else if (!sharp0orInf(s)) return false;
  }
  if (semi && (L.chaikin || (L.base === 0 && creaseVertexGrid(L, x)))) return false;
  for (let k = m.vertHeOffsets[x]; k < m.vertHeOffsets[x + 1]; k++) if (!isQuadHe(m, m.vertHe[k])) return false;
  const ring = vertexRing(m, x);
  if (!ring || ring.he.length === 0) return false;
  const n = ring.he.length;
  if (n + (ring.boundary ? 1 : 0) > CC_MAX_FAN_SECTORS) return false;
  // Axis neighbours: the edges x→e_i (and the trailing boundary edge).
  for (const h of ring.he) {
    if (!axisOk(L, m.faceIndices[m.heNext[h]], L.edgeSharp[m.heEdge[h]])) return false;
  }
  if (ring.boundary) {
    const hl = m.hePrev[ring.he[n - 1]];
    if (!axisOk(L, m.faceIndices[hl], L.edgeSharp[m.heEdge[hl]])) return false;
  }
  // Diagonals: smooth interior valence-4 vertices.
  for (const h of ring.he) {
    const z = m.faceIndices[m.heNext[m.heNext[h]]];
    if (L.boundary[z] || L.vertSharp[z] !== 0) return false;
    if (m.vertHeOffsets[z + 1] - m.vertHeOffsets[z] !== 4 || m.vertEdgeOffsets[z + 1] - m.vertEdgeOffsets[z] !== 4) return false;
    for (let k = m.vertEdgeOffsets[z]; k < m.vertEdgeOffsets[z + 1]; k++) if (L.edgeSharp[m.vertEdges[k]] !== 0) return false;
    for (let k = m.vertHeOffsets[z]; k < m.vertHeOffsets[z + 1]; k++) if (!isQuadHe(m, m.vertHe[k])) return false;
  }
  return true;
}

const exponentCache = new Map<string, number>();

/**
 * Radial blend exponent α = −log2 λ of a fan that is not a smooth interior vertex (creases,
 * corners, darts, boundaries): λ is the largest eigenvalue but 1 of one subdivision step of the
 * fan's 1-ring (c, e_i, d_i), found by power iteration on the ring modulo the constant vector
 * (a topological quantity: the same slice rules as wgsl/cc/build.wgsl, on scalars). A cone
 * apex (corner with smooth edges) has λ ≈ 0.65, not ½: the radial blend needs it.
 */
function ringExponent(n: number, boundary: boolean, rule: number, ia: number, ib: number, inf: number[]): number {
  const key = `${n} ${boundary ? 1 : 0} ${rule} ${ia} ${ib} ${inf.join('')}`;
  const hit = exponentCache.get(key);
  if (hit !== undefined) return hit;
  const ns = inf.length;
  let c = 0;
  let e = Array.from({ length: ns }, (_, i) => Math.sin(1.7 * i + 0.3) + 0.5);
  let d = Array.from({ length: n }, (_, i) => Math.cos(2.3 * i + 0.1) - 0.2);
  let lambda = 0.5;
  for (let it = 0; it < 200; it++) {
    const nx = (i: number) => (boundary ? i + 1 : (i + 1) % n);
    const F = d.map((di, i) => 0.25 * (c + e[i] + di + e[nx(i)]));
    const e1 = e.map((ei, i) => {
      if (inf[i]) return 0.5 * (c + ei);
      const fp = boundary ? F[i - 1] : F[(i + n - 1) % n];
      return 0.25 * (c + ei + F[i] + fp);
    });
    let c1 = c;
    if (rule === VRULE_CREASE) c1 = 0.75 * c + 0.125 * (e[ia] + e[ib]);
    else if (rule === VRULE_SMOOTH)
      c1 = ((n - 2) / n) * c + (e.slice(0, n).reduce((a, b) => a + b, 0) + F.reduce((a, b) => a + b, 0)) / (n * n);
    // Modulo the constant vector: shift the centre to 0.
    const e2 = e1.map((x) => x - c1),
      d2 = F.map((x) => x - c1);
    const norm = Math.hypot(...e2, ...d2);
    const prev = Math.hypot(...e.map((x) => x - c), ...d.map((x) => x - c));
    if (!(norm > 0) || !(prev > 0)) break;
    lambda = norm / prev;
    e = e2.map((x) => x / norm);
    d = d2.map((x) => x / norm);
    c = 0;
  }
  const alpha = lambda > 0 && lambda < 1 ? -Math.log2(lambda) : 1;
  exponentCache.set(key, alpha);
  return alpha;
}

/** Subdominant eigenvalue of the smooth Catmull-Clark rule at interior valence n. */
export function subdominantEigenvalue(n: number): number {
  const th = (2 * Math.PI) / n;
  return (5 + Math.cos(th) + Math.cos(th / 2) * Math.sqrt(2 * (9 + Math.cos(th)))) / 16;
}

export interface FanRec {
  level: number;
  x: number;
  n: number;
  boundary: boolean;
  D: number;
  rule: number;
  ia: number;
  ib: number;
  alpha: number;
  cageVertex: number;
  /** Per thread: its 6 global point indices ((1,0) (2,0) (1,1) (2,1) (1,2) (2,2) at level s). */
  sectors: number[][];
  /** Per thread: its axis's sharpness at level s (0, σ, or SHARPNESS_INFINITE); packed as the
   * sector's axis word (axisWord). */
  axis: number[];
  /** The centre's vertex sharpness at level s (0, semi-sharp, or infinite). */
  vertexSharp: number;
  /** The level-s face of each sector. */
  ringFaces: number[];
}

/** The fan of x at level l: its sectors' points (global indices), its rule and its radial blend exponent; D stays 0 until a region asks for depth. */
function makeFan(L: Level, l: number, x: number): FanRec {
  const m = L.he;
  const ring = vertexRing(m, x)!;
  const n = ring.he.length;
  const G = (v: number) => L.base + v;
  const fi = m.faceIndices,
    nx = m.heNext;
  const sectors: number[][] = [];
  const axis: number[] = [];
  let nInf = 0,
    ia = 0,
    ib = 0;
  for (let i = 0; i < n; i++) {
    const h = ring.he[i];
    const sharpness = L.edgeSharp[m.heEdge[h]];
    const inf = sharpness >= INF ? 1 : 0;
    axis.push(inf ? INF : sharpness);
    if (inf) {
      if (nInf === 0) ia = i;
      else ib = i;
      nInf++;
    }
    const t = m.heTwin[nx[h]];
    const u = m.heTwin[nx[nx[nx[t]]]];
    sectors.push([G(fi[nx[h]]), G(fi[nx[nx[t]]]), G(fi[nx[nx[h]]]), G(fi[nx[nx[nx[t]]]]), G(fi[nx[nx[nx[u]]]]), G(fi[nx[nx[u]]])]);
  }
  if (ring.boundary) {
    const hl = ring.he[n - 1];
    const w = m.heTwin[nx[nx[hl]]];
    sectors.push([G(fi[m.hePrev[hl]]), G(fi[m.hePrev[w]]), G(x), G(x), G(x), G(x)]);
    axis.push(INF);
    ib = n;
    nInf++;
  }
  const vs = L.vertSharp[x];
  // The rule after every semi-sharp value has decayed (the limits kernel's; the slices take the
  // rule of each step from stepRules).
  const vsFinal = vs >= INF ? vs : 0;
  const rule = vertexRuleOf(nInf, vsFinal);
  const smoothInterior = !ring.boundary && nInf === 0 && vsFinal === 0 && n >= 3;
  const inf = axis.map((a) => (a >= INF ? 1 : 0));
  return {
    level: l,
    x,
    n,
    boundary: ring.boundary,
    D: 0,
    rule,
    ia,
    ib,
    cageVertex: -1,
    sectors,
    axis,
    vertexSharp: vs,
    ringFaces: ring.he.map((h) => m.heFace[h]),
    alpha: smoothInterior ? -Math.log2(subdominantEigenvalue(n)) : ringExponent(n, ring.boundary, rule, ia, ib, inf),
  };
}

/**
 * The fans met so far, keyed by (start level, vertex), each at the deepest depth any region or
 * vertex asked of it: regions and vertex limits share a fan, and a fan's id is its place here.
 */
export interface FanTable {
  fans: FanRec[];
  /** The coarsest level ≤ upTo at which x is a fan centre, or -1. */
  fanStart: (x: number, upTo: number) => number;
  /** The id of the fan of x starting at level l (made on first use), deepened to at least D. */
  getFan: (l: number, x: number, D: number, cageVertex?: number) => number;
}

/** An empty fan table over the levels of `level` (src/gpu/cc/levels.ts levelStack). */
export function fanTable(level: (l: number) => Level): FanTable {
  const fans: FanRec[] = [];
  const fanAt = new Map<number, number>();
  const fanStart = (x: number, upTo: number): number => {
    for (let l = 0; l <= upTo; l++) {
      const L = level(l);
      if (x < L.he.nVerts && L.he.vertHeOffsets[x + 1] > L.he.vertHeOffsets[x] && isEligible(L, x)) return l;
    }
    return -1;
  };
  const getFan = (l: number, x: number, D: number, cageVertex = -1): number => {
    const key = l * 0x4000000 + x;
    let id = fanAt.get(key);
    if (id === undefined) {
      id = fans.length;
      fanAt.set(key, id);
      fans.push(makeFan(level(l), l, x));
    }
    const F = fans[id];
    F.D = Math.max(F.D, D);
    if (cageVertex >= 0) F.cageVertex = cageVertex;
    return id;
  };
  return { fans, fanStart, getFan };
}

/**
 * The vfan words: every prepared vertex's limit rule. The emit passes read a vertex's limit
 * (position and normal for the factor rule) through it, so each gets a fan (its slices may be
 * empty) or a crease record, appended to patchIdx.
 */
export function vertexLimits(prepared: PreparedMesh, topo: HalfEdges, lv: LevelStack, ft: FanTable, patchIdx: U32): Uint32Array {
  const nV0 = topo.nVerts;
  const { levels, level } = lv;
  const { getFan } = ft;
  // Every prepared vertex's limit (the factor rule, the flat baseline) comes from its fan, or on
  // a straight semi-sharp crease from the closed form (no level refined for it). A cage vertex
  // is x = v at level 0; a face's centre vertex (prepare.ts) is its face point, the level-1
  // vertex nV + nE + f (a vertex point keeps its index at every finer level).
  const vertexFan = new Uint32Array(prepared.vertexCount).fill(CC_NONE);
  for (let c = nV0; c < prepared.vertexCount; c++) {
    const o = prepared.vertexOwner[c];
    if (o === NO_OWNER) continue;
    const f = prepared.triFace[OWNER_WORD.unpack(o).tri];
    const x = nV0 + topo.nEdges + f;
    let s = -1;
    for (let l = 1; l <= MAX_LEVEL && s < 0; l++) if (isEligible(level(l), x)) s = l;
    if (s < 0) throw new Error(`Catmull-Clark: no limit rule for the centre of face ${f}`);
    vertexFan[c] = getFan(s, x, 0);
  }
  for (let v = 0; v < nV0; v++) {
    if (topo.vertHeOffsets[v + 1] === topo.vertHeOffsets[v]) continue;
    if (!isEligible(levels[0], v)) {
      const cv = creaseVertexGrid(levels[0], v);
      if (cv) {
        vertexFan[v] = CC_VERTEX_LIMIT_WORD.pack({ index: patchIdx.n, crease: 1 });
        for (const p of cv.idx) patchIdx.push(p);
        patchIdx.push(f32bits(cv.sigma));
        continue;
      }
    }
    let s = -1;
    for (let l = 0; l <= MAX_LEVEL && s < 0; l++) if (isEligible(level(l), v)) s = l;
    if (s < 0) throw new Error(`Catmull-Clark: no limit rule for vertex ${v}`);
    vertexFan[v] = getFan(s, v, 0, v);
  }
  return vertexFan;
}

/**
 * Which steps' sector points a fan's slices keep (src/gpu/cc/build.ts "slices"): every step's, so
 * a vertex reads its sub-patch as it is, or the odd steps' only (half the bytes), so a vertex on an
 * even step's sub-patch makes its points by one step from the stored step before (the slice
 * kernel's own sliceStep, wgsl/cc/slices.wgsl).
 */
export type SliceSteps = 'every' | 'odd';

/** The steps whose sector points a fan of depth D keeps. */
export const storedSteps = (D: number, odd: boolean): number => (odd ? Math.ceil(D / 2) : D);

/**
 * A fan's final depth: the depth its regions and vertex limit asked for, and round creases,
 * corners, darts and boundaries 2^-3 smaller still: the radial blend's one exponent is a rougher
 * model there (two rates, along and across).
 */
function fanDepth(F: FanRec, semi: number): number {
  let D = F.D;
  if (D > 0 && !(F.rule === VRULE_SMOOTH && !F.boundary && F.axis.every((a) => a === 0))) D = Math.min(15, D + EXTRA_DEPTH_SHARP);
  // Semi-sharp values (the largest: `semi`) decay inside the slices, and the limit is taken after
  // they have: at least ceil(σ) + 1 steps, whether or not a region reads the slices (the limits
  // kernel reads the last step's ring with the fan's final rule).
  return semi > 0 ? Math.max(D, Math.ceil(semi) + 1) : D;
}

/** A sector's axis word (src/gpu/cc/build.ts "sectors") from its axis's sharpness. */
const axisWord = (a: number): number => (a >= INF ? CC_AXIS_INFINITE : a > 0 ? f32bits(a) : 0);

/** The largest semi-sharp value of a fan, its axes' and its centre's (0: none). */
const semiSharpest = (F: FanRec): number =>
  F.axis.reduce((m, a) => (isSemi(a) ? Math.max(m, a) : m), isSemi(F.vertexSharp) ? F.vertexSharp : 0);

/**
 * The centre's rule in each step k = 1..D of a fan with semi-sharp values (3 words a step: its
 * CC_STEP_RULE_WORD, its crease pair, W as f32 bits): src/gpu/cc/levels.ts vertexStep, which makes
 * the levels' vertex points' too, on the axes' and the centre's sharpness before and after the
 * step (uniform creasing: one unit less each step).
 */
function stepRules(F: FanRec, D: number): number[] {
  const words: number[] = [];
  const step: VertexStep = { parent: 0, child: 0, a: 0, b: 0, W: 1 };
  let before = F.axis;
  let vs = F.vertexSharp;
  for (let k = 1; k <= D; k++) {
    const after = before.map(decSharp);
    const { parent, child, a, b, W } = vertexStep(before, after, vs, decSharp(vs), step);
    words.push(CC_STEP_RULE_WORD.pack({ parent, child }), CC_PAIR_WORD.pack({ a, b }), f32bits(W));
    before = after;
    vs = decSharp(vs);
  }
  return words;
}

/** The fans' words and their places in the point space (after the levels), and which fans have slices. */
export interface PackedFans {
  fanWords: U32;
  sectorWords: U32;
  cosWords: U32;
  /** The deepest fan. */
  maxDepth: number;
  /** The fans with D > 0, in id order: the slice kernel's work. */
  sliceFans: number[];
  /** One past the last point (global index): the levels', the slices' and the limits'. */
  nextPoint: number;
  /** Some fan has an infinitely sharp axis (its sub-patches take phantom points there). */
  axisPhantoms: boolean;
  /** Some sliced fan has a semi-sharp axis (its sub-patches next to it take the crease basis). */
  semiAxes: boolean;
}

/**
 * Lay the fans out after the last level, once every region and vertex limit has asked for its
 * fan (their depths are final): each fan's slices and limits in the point space, its words, and
 * the cos table of each smooth valence.
 */
export function packFans(fans: FanRec[], levels: Level[], slices: SliceSteps = 'every'): PackedFans {
  // Points: the levels, then per fan its slices and limits.
  const lastLevel = levels[levels.length - 1];
  let nextPoint = lastLevel.base + lastLevel.he.nVerts;
  const fanWords = new U32(),
    sectorWords = new U32(),
    cosWords = new U32();
  const cosAt = new Map<number, number>();
  let maxDepth = 0;
  let axisPhantoms = false;
  let semiAxes = false;
  const sliceFans: number[] = [];
  fans.forEach((F, id) => {
    const sharpest = semiSharpest(F);
    const semi = sharpest > 0;
    const D = fanDepth(F, sharpest);
    const ns = F.sectors.length;
    // A fan wider than a workgroup reads each step before from its stored slice (wgsl/cc/build.wgsl
    // wideSlices), so it keeps every step.
    const odd = slices === 'odd' && ns <= WORKGROUP_SIZE;
    const sliceBase = nextPoint;
    nextPoint += D + 12 * storedSteps(D, odd) * ns;
    const limitBase = nextPoint;
    nextPoint += 3 + (F.rule === VRULE_SMOOTH ? 0 : 2 * F.n);
    maxDepth = Math.max(maxDepth, D);
    let cosBase = 0;
    if (F.rule === VRULE_SMOOTH && !F.boundary) {
      let at = cosAt.get(F.n);
      if (at === undefined) {
        cosAt.set(F.n, (at = cosWords.n));
        for (let i = 0; i < F.n; i++) cosWords.push(f32bits(Math.cos((2 * Math.PI * i) / F.n)));
        cosWords.push(f32bits(1 / (4 * subdominantEigenvalue(F.n) - 1)));
      }
      cosBase = at;
    }
    if (D > 15) throw new Error('fan depth > 15');
    fanWords.push(CC_FAN_WORD.pack({ sectors: ns, valence: F.n, boundary: F.boundary, rule: F.rule, depth: D, odd }));
    fanWords.push(levels[F.level].base + F.x);
    fanWords.push(sliceBase);
    fanWords.push(sectorWords.n);
    fanWords.push(f32bits(F.alpha));
    fanWords.push(limitBase);
    fanWords.push(CC_PAIR_WORD.pack({ a: F.ia, b: F.ib }));
    fanWords.push(cosBase);
    F.sectors.forEach((points, i) => {
      sectorWords.push(axisWord(F.axis[i]));
      for (const p of points) sectorWords.push(p);
    });
    // Word 8: where the centre's per-step rules start in the sectors' words (a fan with a
    // semi-sharp value), else CC_NONE (its one rule, word 0's, in every step).
    fanWords.push(semi ? sectorWords.n : CC_NONE);
    if (semi) for (const w of stepRules(F, D)) sectorWords.push(w);
    if (D > 0) sliceFans.push(id);
    if (D > 0 && F.axis.some((a) => a >= INF)) axisPhantoms = true;
    if (D > 0 && semi) semiAxes = true;
  });
  return { fanWords, sectorWords, cosWords, maxDepth, sliceFans, nextPoint, axisPhantoms, semiAxes };
}

/** The slice kernel's thread words: one thread per sector of each sliced fan; a fan wider than a
 * workgroup gets one of its own (CC_WIDE_FAN in its first word: its threads loop over its sectors). */
export function packThreads(fans: FanRec[], sliceFans: number[]): U32 {
  // Pack the sliced fans into workgroups of 64 threads (a fan never straddles two).
  const threadWords = new U32();
  let used = WORKGROUP_SIZE;
  for (const id of sliceFans) {
    const ns = fans[id].sectors.length;
    if (ns > WORKGROUP_SIZE) {
      while (threadWords.n % WORKGROUP_SIZE) threadWords.push(CC_NONE);
      threadWords.push(CC_THREAD_WORD.pack({ fan: id, sector: CC_WIDE_FAN }));
      while (threadWords.n % WORKGROUP_SIZE) threadWords.push(CC_NONE);
      used = WORKGROUP_SIZE;
      continue;
    }
    if (used + ns > WORKGROUP_SIZE) {
      while (threadWords.n % WORKGROUP_SIZE) threadWords.push(CC_NONE);
      used = 0;
    }
    for (let i = 0; i < ns; i++) threadWords.push(CC_THREAD_WORD.pack({ fan: id, sector: i }));
    used += ns;
  }
  while (threadWords.n % WORKGROUP_SIZE) threadWords.push(CC_NONE);
  return threadWords;
}
