/**
 * The uniform levels of the Catmull-Clark preparation (part 1 of the header of src/gpu/cc/build.ts):
 * each level's topology and sharpness, the rule and inputs of every point one refinement makes,
 * and the per-level caches of which vertices are regular. Topology only: the GPU makes the points
 * from these rules (wgsl/cc/build.wgsl).
 */
import { LimitError } from '../../mesh/errors.ts';
import {
  type HalfEdges,
  type Sharpness,
  SHARPNESS_INFINITE,
  childEdgeSharpAtVertex,
  decSharp,
  isRegularVertex,
  vertexAdjacency,
} from '../../mesh/index.ts';
import { CC_PAIR_WORD, CC_RULE_WORD } from './words.ts';
import { U32, f32bits } from './word-list.ts';

export const RULE_FACE = 0;
export const RULE_EDGE = 1;
export const RULE_VERTEX = 2;
export const VRULE_SMOOTH = 0;
export const VRULE_CREASE = 1;
export const VRULE_CORNER = 2;
/** Deepest uniform level tried before a face is declared unsupported. */
export const MAX_LEVEL = 6;

export interface Level {
  he: HalfEdges;
  edgeSharp: Float64Array;
  vertSharp: Float64Array;
  hole: Uint8Array;
  boundary: Uint8Array;
  /** Global point index of this level's vertex 0. */
  base: number;
  regular: Int8Array; // -1 unknown
  eligible: Int8Array; // -1 unknown
  /** Chaikin's creasing rule (refineLevel): its sharpness decays by each edge's neighbours too. */
  chaikin: boolean;
}

const INF = SHARPNESS_INFINITE;

function makeLevel(
  he: HalfEdges,
  edgeSharp: Float64Array,
  vertSharp: Float64Array,
  hole: Uint8Array,
  base: number,
  chaikin: boolean,
): Level {
  const boundary = new Uint8Array(he.nVerts);
  for (let e = 0; e < he.nEdges; e++)
    if (he.edgeFaceCount[e] === 1) {
      boundary[he.edgeVerts[2 * e]] = 1;
      boundary[he.edgeVerts[2 * e + 1]] = 1;
    }
  return {
    he,
    edgeSharp,
    vertSharp,
    hole,
    boundary,
    base,
    regular: new Int8Array(he.nVerts).fill(-1),
    eligible: new Int8Array(he.nVerts).fill(-1),
    chaikin,
  };
}

export function vertexRuleOf(nSharp: number, vs: number): number {
  if (vs > 0 || nSharp >= 3) return VRULE_CORNER;
  return nSharp === 2 ? VRULE_CREASE : VRULE_SMOOTH; // 0: smooth, 1: dart (smooth mask)
}

/** A vertex point's rules in one step (OpenSubdiv's Catmull-Clark vertex rule with its transition). */
export interface VertexStep {
  parent: number;
  child: number;
  /** The crease pair, as indices into the edges given: the parent's if it is a crease, else the child's. */
  a: number;
  b: number;
  /** Where the rules differ, the parent's weight: the mean sharpness of the values whose sharpness
   * ends at this step (OpenSubdiv's fractional weight; under Chaikin, the edges whose child at the
   * vertex is smooth). */
  W: number;
}

/**
 * The rules of a vertex point from the sharpness of its edges before (`ps`) and after (`cs`, the
 * children at this vertex) the step, and its own before and after (`vs`, `vsChild`): the levels'
 * vertex points (refineLevel) and a fan centre's steps (src/gpu/cc/fans.ts stepRules) alike.
 * Written into `out` (no allocation per vertex).
 */
export function vertexStep(ps: ArrayLike<number>, cs: ArrayLike<number>, vs: number, vsChild: number, out: VertexStep): VertexStep {
  let nP = 0,
    nC = 0,
    pa = 0,
    pb = 0,
    ca = 0,
    cb = 0,
    tSum = 0,
    tCount = 0;
  if (vs > 0 && vsChild === 0) {
    tSum = Math.fround(vs);
    tCount = 1;
  }
  for (let i = 0; i < ps.length; i++) {
    const s = ps[i],
      c = cs[i];
    if (s > 0) {
      if (nP === 0) pa = i;
      else if (nP === 1) pb = i;
      nP++;
    }
    if (c > 0) {
      if (nC === 0) ca = i;
      else if (nC === 1) cb = i;
      nC++;
    }
    if (s > 0 && !(c > 0)) {
      tSum = Math.fround(tSum + s);
      tCount++;
    }
  }
  out.parent = vertexRuleOf(nP, vs);
  out.child = vertexRuleOf(nC, vsChild);
  out.W = 1;
  if ((out.parent === VRULE_CREASE || out.parent === VRULE_CORNER) && out.child !== out.parent) {
    out.W = tCount ? Math.min(1, Math.fround(tSum / tCount)) : 0;
  } else out.child = out.parent;
  const own = out.parent === VRULE_CREASE;
  out.a = own ? pa : ca;
  out.b = own ? pb : cb;
  return out;
}

/**
 * Refine level L's topology once: the rules of level L+1's points, and level L+1. Each new edge
 * (v, E(e)) takes the sharpness of e's child at v: e's less one (uniform creasing), or under
 * Chaikin's rule (`chaikin`) also averaged with the other semi-sharp edges at v
 * (childEdgeSharpAtVertex), so the two halves of an edge may differ.
 */
function refineLevel(L: Level, rules: U32, inputs: U32, chaikin: boolean): Level {
  const m = L.he;
  const nV = m.nVerts,
    nE = m.nEdges,
    nF = m.nFaces;
  const base1 = L.base + nV;
  const fBase = base1 + nV + nE,
    vBase = L.base;
  // The child sharpness of each edge at each of its ends, in the vertices' edge order (vertEdges).
  const childAt = new Float64Array(m.vertEdges.length);
  const ps: number[] = [],
    cs: number[] = [];
  const step: VertexStep = { parent: 0, child: 0, a: 0, b: 0, W: 1 };
  // The words are written straight into the lists, room made for the most a level can take
  // (a vertex: itself, its edges' far ends, its faces, a crease pair and W; an edge: 4 and σ; a
  // face: its corners), and the rule words of the few kinds a level has packed once each
  // (ruleWord): a cage's first preparation runs this loop cold, once per refined point.
  const nHp = m.faceIndices.length;
  const inA = inputs.reserve(3 * nV + 2 * nE + nHp + 5 * nE + nHp);
  const ruA = rules.reserve(2 * (nV + nE + nF));
  let inN = inputs.n,
    ruN = rules.n;
  const ruleWords = new Map<number, number>();
  const ruleWord = (kind: number, parent: number, child: number, sharp: boolean, count: number, faces: number): number => {
    const key = kind + 4 * (parent + 4 * (child + 4 * ((sharp ? 1 : 0) + 2 * (count + 65536 * faces))));
    let w = ruleWords.get(key);
    if (w === undefined) {
      w = CC_RULE_WORD.pack({ kind, parent, child, sharp, count, faces });
      ruleWords.set(key, w);
    }
    return w;
  };
  // The rule word's count and faces fields (CC_RULE_WORD) bound the valence this build takes.
  const most = Math.min(2 ** CC_RULE_WORD.fields.count[1], 2 ** CC_RULE_WORD.fields.faces[1]) - 1;
  // Vertex points.
  for (let v = 0; v < nV; v++) {
    const e0 = m.vertEdgeOffsets[v],
      e1 = m.vertEdgeOffsets[v + 1];
    const h0 = m.vertHeOffsets[v],
      h1 = m.vertHeOffsets[v + 1];
    const first = inN;
    inA[inN++] = vBase + v;
    const vs = L.vertSharp[v];
    // A smooth vertex (no sharp edge, no vertex sharpness; most of them) keeps the smooth rule in
    // both steps and its edges' children stay smooth (childAt's zeros): no sharpness lists made.
    let sharpHere = vs !== 0;
    for (let k = e0; k < e1 && !sharpHere; k++) sharpHere = L.edgeSharp[m.vertEdges[k]] !== 0;
    if (sharpHere) {
      ps.length = 0;
      for (let k = e0; k < e1; k++) ps.push(L.edgeSharp[m.vertEdges[k]]);
      childEdgeSharpAtVertex(ps, chaikin, cs);
      for (let k = e0; k < e1; k++) childAt[k] = cs[k - e0];
      vertexStep(ps, cs, vs, decSharp(vs), step);
    } else {
      step.parent = step.child = VRULE_SMOOTH;
    }
    for (let k = e0; k < e1; k++) {
      const e = m.vertEdges[k];
      inA[inN++] = vBase + m.edgeVerts[2 * e] + m.edgeVerts[2 * e + 1] - v;
    }
    for (let k = h0; k < h1; k++) inA[inN++] = fBase + m.heFace[m.vertHe[k]];
    const pr = step.parent,
      cr = step.child;
    if (e1 - e0 > most || h1 - h0 > most)
      throw new LimitError(`a vertex of valence ${e1 - e0} is not supported by the Catmull-Clark build (at most ${most})`);
    ruA[ruN++] = ruleWord(RULE_VERTEX, pr, cr, false, e1 - e0, h1 - h0);
    ruA[ruN++] = first;
    // A sharp vertex (either rule not smooth) carries its crease pair and W after its inputs.
    if (pr !== VRULE_SMOOTH || cr !== VRULE_SMOOTH) {
      inA[inN++] = CC_PAIR_WORD.pack({ a: step.a, b: step.b });
      inA[inN++] = f32bits(step.W);
    }
  }
  // Edge points.
  for (let e = 0; e < nE; e++) {
    const first = inN;
    inA[inN++] = vBase + m.edgeVerts[2 * e];
    inA[inN++] = vBase + m.edgeVerts[2 * e + 1];
    let n = 2;
    if (m.edgeFaceCount[e] === 2) {
      const h = m.edgeHe[e];
      inA[inN++] = fBase + m.heFace[h];
      inA[inN++] = fBase + m.heFace[m.heTwin[h]];
      n = 4;
    }
    // An interior edge with sharpness carries it after its inputs (flag bit 2).
    const sharpEdge = n === 4 && L.edgeSharp[e] !== 0;
    if (sharpEdge) inA[inN++] = f32bits(L.edgeSharp[e]);
    ruA[ruN++] = ruleWord(RULE_EDGE, 0, 0, sharpEdge, n, 0);
    ruA[ruN++] = first;
  }
  // Face points.
  for (let f = 0; f < nF; f++) {
    const a = m.faceOffsets[f],
      b = m.faceOffsets[f + 1];
    if (b - a >= 2 ** CC_RULE_WORD.fields.count[1])
      throw new LimitError(
        `a face of ${b - a} corners is not supported by the Catmull-Clark build (at most ${2 ** CC_RULE_WORD.fields.count[1] - 1})`,
      );
    ruA[ruN++] = ruleWord(RULE_FACE, 0, 0, false, b - a, 0);
    ruA[ruN++] = inN;
    for (let h = a; h < b; h++) inA[inN++] = vBase + m.faceIndices[h];
  }
  // A typed array drops writes past its end: the room above is a bound, held here.
  if (inN > inA.length || ruN > ruA.length) throw new Error('refineLevel: a level wrote more words than it made room for');
  inputs.n = inN;
  rules.n = ruN;
  // Level L+1 topology.
  const nHe = nHp;
  const faceOffsets = new Int32Array(nHe + 1);
  const faceIndices = new Int32Array(4 * nHe);
  const hole = new Uint8Array(nHe);
  for (let h = 0; h < nHe; h++) {
    faceOffsets[h + 1] = 4 * (h + 1);
    faceIndices[4 * h] = m.faceIndices[h];
    faceIndices[4 * h + 1] = nV + m.heEdge[h];
    faceIndices[4 * h + 2] = nV + nE + m.heFace[h];
    faceIndices[4 * h + 3] = nV + m.heEdge[m.hePrev[h]];
    hole[h] = L.hole[m.heFace[h]];
  }
  const nV1 = nV + nE + nF;
  const he = refinedHalfEdges(m, nV1, faceOffsets, faceIndices);
  const edgeSharp = new Float64Array(he.nEdges);
  for (let e = 0; e < he.nEdges; e++) {
    const a = he.edgeVerts[2 * e],
      b = he.edgeVerts[2 * e + 1];
    const lo = Math.min(a, b),
      hi = Math.max(a, b);
    if (lo < nV && hi >= nV && hi < nV + nE) {
      const parent = hi - nV;
      for (let k = m.vertEdgeOffsets[lo]; k < m.vertEdgeOffsets[lo + 1]; k++) if (m.vertEdges[k] === parent) edgeSharp[e] = childAt[k];
    }
  }
  const vertSharp = new Float64Array(nV1);
  for (let v = 0; v < nV; v++) vertSharp[v] = decSharp(L.vertSharp[v]);
  return makeLevel(he, edgeSharp, vertSharp, hole, base1, chaikin);
}

/**
 * Half-edges of a refined level without a hash map: child face h (parent half-edge h) is
 * [V, E_h, F, E_prev(h)] and its 4 half-edges 4h..4h+3 pair with known neighbours: (V→E_h) with
 * the last half-edge of the child of next(twin h); (E_h→F) with (F→E_h) of next(h)'s child;
 * (F→E_p) with (E_p→F) of prev(h)'s child; (E_p→V) with the first of twin(prev h)'s child.
 */
function refinedHalfEdges(m: HalfEdges, nVerts: number, faceOffsets: Int32Array, faceIndices: Int32Array): HalfEdges {
  const nHp = m.faceIndices.length;
  const nHe = 4 * nHp;
  const heFace = new Int32Array(nHe),
    heNext = new Int32Array(nHe),
    hePrev = new Int32Array(nHe),
    heTwin = new Int32Array(nHe);
  for (let h = 0; h < nHp; h++) {
    const b = 4 * h;
    for (let j = 0; j < 4; j++) {
      heFace[b + j] = h;
      heNext[b + j] = b + ((j + 1) & 3);
      hePrev[b + j] = b + ((j + 3) & 3);
    }
    const t = m.heTwin[h],
      tp = m.heTwin[m.hePrev[h]];
    heTwin[b] = t >= 0 ? 4 * m.heNext[t] + 3 : -1;
    heTwin[b + 1] = 4 * m.heNext[h] + 2;
    heTwin[b + 2] = 4 * m.hePrev[h] + 1;
    heTwin[b + 3] = tp >= 0 ? 4 * tp : -1;
  }
  const heEdge = new Int32Array(nHe);
  let nEdges = 0;
  for (let h = 0; h < nHe; h++) if (heTwin[h] < 0 || h < heTwin[h]) nEdges++;
  const edgeVerts = new Int32Array(2 * nEdges),
    edgeFaceCount = new Int32Array(nEdges),
    edgeHe = new Int32Array(nEdges);
  let e = 0;
  for (let h = 0; h < nHe; h++) {
    const t = heTwin[h];
    if (t >= 0 && t < h) {
      heEdge[h] = heEdge[t];
      continue;
    }
    heEdge[h] = e;
    edgeVerts[2 * e] = faceIndices[h];
    edgeVerts[2 * e + 1] = faceIndices[heNext[h]];
    edgeFaceCount[e] = t >= 0 ? 2 : 1;
    edgeHe[e] = h;
    e++;
  }
  const { vertHeOffsets, vertHe, vertEdgeOffsets, vertEdges } = vertexAdjacency(nVerts, faceIndices, edgeVerts);
  return halfEdgesOf({
    nVerts,
    nFaces: nHp,
    nEdges,
    faceOffsets,
    faceIndices,
    heFace,
    heNext,
    hePrev,
    heTwin,
    heEdge,
    edgeVerts,
    edgeFaceCount,
    edgeHe,
    vertHeOffsets,
    vertHe,
    vertEdgeOffsets,
    vertEdges,
  });
}

/**
 * The half-edges alone, as one object shape for every level: the cage's topology carries more
 * fields (src/mesh/topology.ts Topology), and a level function that met both shapes was compiled
 * for one, thrown away on meeting the other ("wrong map") and compiled again, on every level. A
 * cage's first preparation runs this code cold (the user's wait), so it matters there.
 */
function halfEdgesOf(m: HalfEdges): HalfEdges {
  return {
    nVerts: m.nVerts,
    nFaces: m.nFaces,
    nEdges: m.nEdges,
    faceOffsets: m.faceOffsets,
    faceIndices: m.faceIndices,
    heFace: m.heFace,
    heNext: m.heNext,
    hePrev: m.hePrev,
    heTwin: m.heTwin,
    heEdge: m.heEdge,
    edgeVerts: m.edgeVerts,
    edgeFaceCount: m.edgeFaceCount,
    edgeHe: m.edgeHe,
    vertHeOffsets: m.vertHeOffsets,
    vertHe: m.vertHe,
    vertEdgeOffsets: m.vertEdgeOffsets,
    vertEdges: m.vertEdges,
  };
}

export function isRegular(L: Level, v: number): boolean {
  if (L.regular[v] < 0) L.regular[v] = isRegularVertex(L.he, v, L.edgeSharp, L.vertSharp, !!L.boundary[v]) ? 1 : 0;
  return L.regular[v] === 1;
}

export function isQuadHe(m: HalfEdges, h: number): boolean {
  return m.faceOffsets[m.heFace[h] + 1] - m.faceOffsets[m.heFace[h]] === 4;
}

/**
 * The uniform levels of a cage, refined on demand: level(l) refines the whole cage up to level l
 * the first time a face or a fan needs it, so a cage gets only as many levels as its worst face
 * (G in the header of src/gpu/cc/build.ts). Refining appends the new points' rules and inputs and
 * the level's dispatch ranges, in the order the levels are made.
 */
export interface LevelStack {
  levels: Level[];
  rules: U32;
  inputs: U32;
  /** Global point index ranges for the level dispatches: per level [faceFirst, faceCount, veFirst, veCount]. */
  levelRanges: [number, number, number, number][];
  level: (l: number) => Level;
}

/** Level 0 (the cage) and the means to refine further; refuses levels past MAX_LEVEL with the cage's sharpest crease. */
export function levelStack(topo: HalfEdges, sharp: Sharpness, chaikin = false): LevelStack {
  const levels: Level[] = [makeLevel(halfEdgesOf(topo), sharp.edge, sharp.vertex, sharp.hole, 0, chaikin)];
  const rules = new U32(),
    inputs = new U32();
  const levelRanges: [number, number, number, number][] = [];
  const maxSemiSharp = (): number => {
    let m = 0;
    for (const x of sharp.edge) if (x < INF) m = Math.max(m, x);
    for (const x of sharp.vertex) if (x < INF) m = Math.max(m, x);
    return m;
  };
  const level = (l: number): Level => {
    if (l > MAX_LEVEL)
      throw new LimitError(
        `Catmull-Clark: a face needs more than ${MAX_LEVEL} levels of refinement (` +
          (chaikin
            ? "under Chaikin's creasing rule semi-sharp creases decay in levels of the whole cage"
            : 'a semi-sharp crease that is neither a single crease nor the axis of a fan decays in levels of the whole cage') +
          `, one per unit of sharpness; this cage has sharpness up to ${+maxSemiSharp().toPrecision(3)}: not supported)`,
      );
    while (levels.length <= l) {
      const L = levels[levels.length - 1];
      const N = refineLevel(L, rules, inputs, chaikin);
      const nV = L.he.nVerts,
        nE = L.he.nEdges,
        nF = L.he.nFaces;
      levelRanges.push([N.base + nV + nE, nF, N.base, nV + nE]);
      levels.push(N);
    }
    return levels[l];
  };
  return { levels, rules, inputs, levelRanges, level };
}
