/**
 * Catmull-Clark for the compute tessellator: the CPU half, done once per topology.
 *
 * Every cage face (every sub-face k of a face with n ≠ 4 corners) is the root of a small
 * feature-adaptive quadtree, built by the exact CPU reference's local refinement (src/subdiv):
 *   - a node whose face is a regular B-spline patch (src/subdiv/bspline.ts isRegularFace, with
 *     phantom rows/columns for boundaries and infinitely sharp creases) is a PATCH leaf: 16
 *     control points;
 *   - otherwise the node's 1-ring is refined once and it gets 4 children (semi-sharp creases
 *     decay this way, extraordinary vertices shrink to one corner: 3 regular children per level,
 *     the talk's "slices");
 *   - at depth MAX_DEPTH a node still touching an irregular vertex is an UNRESOLVED leaf: the
 *     vertex's exact limit position and tangents (limit masks), blended radially with the
 *     neighbouring regular patches (notes §6.3).
 * Regular quads are 1 region; quads at an extraordinary vertex 4 regions at level 1 and then
 * one irregular corner per level; triangles and n-gons start at their sub-faces (level 1).
 *
 * Control points are not stored as positions but as STENCILS over the cage vertices (weights
 * found by running the reference's own refinement on unit coordinate vectors: subdivision is
 * linear), so the GPU patch-build pass recomputes every control point from the current cage
 * positions every frame (animated cages) with one weighted sum per point. Every patch is
 * re-oriented into its root face's (u,v) frame, so the GPU descent is a plain quadtree walk.
 *
 * Data for the GPU (u32 words, appended to the tessellator's static buffer):
 *   tri      3 words per prepared triangle: root node of the face (of sub-face 0 for n ≠ 4),
 *            n | fan index k << 8 (the triangle is (c0, c_k, c_{k+1}) of its face), and for
 *            n ≠ 4 the first corner of the regular n-gon in `poly`
 *   poly     corners (cos, sin as f32 bits) of the regular n-gons, computed here in f64 (WGSL's
 *            sin, cos and atan2 are far too coarse on some GPUs: 2^-11 absolute in Vulkan)
 *   nodes    4 words each:
 *            INTERNAL  [0, first child (4 consecutive, quadrant i + 2j), 0, 0]
 *            PATCH     [1 | kind << 4, first control point (16, row-major, row ~ v), 0, 0]
 *            UNRESOLVED[2 | corner << 2 | kind << 4 | round(α·4096) << 8, limit point (P, lead,
 *                       trail), sibling across x, sibling across y]
 *   rows     nCtrl + 1 offsets into entries
 *   entries  (cage vertex, f32 weight bits) pairs
 * Control points: patches, then unresolved limits, then (P, lead, trail) of every cage vertex
 * (the limit position and normal the factor rule and the flat baseline use).
 */
import {
  type Cage, type SubdivOptions, DEFAULT_OPTIONS, FaceKind, SHARPNESS_INFINITE, buildTopology, classify, computeSharpness,
  isRegularVertex,
} from '../../mesh/index.ts';
import {
  type Level, extractFaces, faceNeighbourhood, gatherPatch, isBoundaryVertex, isRegularFace, levelFromCage, refine,
  vertexFaces, vertexLimit,
} from '../../subdiv/index.ts';
import type { PreparedMesh } from '../prepare.ts';

export const NODE_INTERNAL = 0;
export const NODE_PATCH = 1;
export const NODE_UNRESOLVED = 2;
export const NO_NODE = 0xffffffff;
/** The control point of a patch stored absolute; the others are offsets from it. */
export const ANCHOR = 5;

/** Patch colours for the demo ("show irregular patches"). */
export const enum PatchKind {
  Regular = 0,
  /** A patch from the refinement of a quad at an irregular vertex (extraordinary, dart, corner...). */
  IrregularQuad = 1,
  /** A patch inside a triangle or n-gon, or a quad next to one. */
  Triangle = 2,
  /** A patch whose refinement was driven by a crease (semi-sharp or a sharp feature). */
  Crease = 3,
}

/** Default depth of the quadtrees (levels below the root face or sub-face). */
export const DEFAULT_MAX_DEPTH = 10;

export interface CatmullClarkOptions {
  /** Depth at which a node still touching an irregular vertex becomes a blended leaf. */
  maxDepth?: number;
  /** Subdivision options (default: the cage file's, over OpenSubdiv's defaults). */
  subdiv?: SubdivOptions;
}

export interface CatmullClarkData {
  /** Static words (layout above), relative offsets of each table. */
  words: Uint32Array;
  offTri: number;
  offPoly: number;
  offNodes: number;
  offRows: number;
  offEntries: number;
  nodeCount: number;
  ctrlCount: number;
  /** First control point of the cage vertex limits (3 per cage vertex). */
  vertexLimitBase: number;
  patchCount: number;
  unresolvedCount: number;
  maxDepth: number;
  /** Per prepared triangle: the face's patch kind (for colours). */
  triKind: Uint8Array;
  /** Host copies for CPU evaluation of the same structure (tests). */
  nodes: Uint32Array;
  alpha: Float32Array;
  rows: Uint32Array;
  entryVertex: Uint32Array;
  entryWeight: Float32Array;
  triRoot: Uint32Array;
  vertexCount: number;
}

/** A level with the stencil of each of its vertices over a support of cage vertices. */
interface SLevel {
  lvl: Level;
  /** Row-major: vertex i's weight on support[j] at W[i·S + j]. */
  W: Float64Array;
}

/** Run a linear function of a level's positions on the stencil columns, 3 at a time. */
function onStencils(s: SLevel, S: number, k: number, f: (l: Level) => ArrayLike<number>): Float64Array {
  const m = s.lvl.he.nVerts;
  const out = new Float64Array(k * S);
  for (let b = 0; b < S; b += 3) {
    const pos = new Float64Array(3 * m);
    for (let i = 0; i < m; i++) for (let c = 0; c < 3 && b + c < S; c++) pos[3 * i + c] = s.W[i * S + b + c];
    const r = f({ ...s.lvl, pos });
    for (let j = 0; j < k; j++) for (let c = 0; c < 3 && b + c < S; c++) out[j * S + b + c] = r[3 * j + c];
  }
  return out;
}

function selectRows(W: Float64Array, S: number, vmap: Int32Array): Float64Array {
  const out = new Float64Array(vmap.length * S);
  for (let i = 0; i < vmap.length; i++) out.set(W.subarray(vmap[i] * S, vmap[i] * S + S), i * S);
  return out;
}

function refineS(s: SLevel, S: number): SLevel {
  const lvl = refine(s.lvl);
  const W = onStencils(s, S, lvl.he.nVerts, (l) => refine(l).pos);
  return { lvl, W };
}

function extractS(s: SLevel, S: number, faces: number[]): SLevel {
  const { level, vmap } = extractFaces(s.lvl, faces);
  return { lvl: level, W: selectRows(s.W, S, vmap) };
}

/** Affine map of the unit square, (X,Y) → (a·X + b·Y + c, d·X + e·Y + f): a node's local frame. */
type Frame = [number, number, number, number, number, number];
const IDENTITY: Frame = [1, 0, 0, 0, 1, 0];

function applyFrame(F: Frame, X: number, Y: number): [number, number] {
  return [F[0] * X + F[1] * Y + F[2], F[3] * X + F[4] * Y + F[5]];
}

/** Quadrant (I,J) of the root-oriented square of a node with frame F: child corner c and child frame. */
function childFrame(F: Frame, I: number, J: number): { c: number; frame: Frame } {
  // Parent-local coordinates as an affine function of the child's root-oriented (X',Y'):
  // X = (I + X')/2, Y = (J + Y')/2.
  const p: Frame = [F[0] / 2, F[1] / 2, F[0] * I / 2 + F[1] * J / 2 + F[2], F[3] / 2, F[4] / 2, F[3] * I / 2 + F[4] * J / 2 + F[5]];
  const [cx, cy] = applyFrame(p, 0.5, 0.5);
  const i = cx >= 0.5 ? 1 : 0, j = cy >= 0.5 ? 1 : 0;
  const c = i === 0 ? (j === 0 ? 0 : 3) : j === 0 ? 1 : 2;
  // The reference's child frames (src/subdiv/evaluate.ts): local (nx, ny) from parent (x, y).
  const X = [p[0], p[1], p[2]], Y = [p[3], p[4], p[5]];
  const lin = (ka: number, A: number[], kb: number, B: number[], k0: number): number[] => [0, 1, 2].map((q) => ka * A[q] + kb * B[q] + (q === 2 ? k0 : 0));
  let nx: number[], ny: number[];
  switch (c) {
    case 0: nx = lin(2, X, 0, Y, 0); ny = lin(0, X, 2, Y, 0); break;
    case 1: nx = lin(0, X, 2, Y, 0); ny = lin(-2, X, 0, Y, 2); break;
    case 2: nx = lin(-2, X, 0, Y, 2); ny = lin(0, X, -2, Y, 2); break;
    default: nx = lin(0, X, -2, Y, 2); ny = lin(2, X, 0, Y, 0); break;
  }
  return { c, frame: [nx[0], nx[1], nx[2], ny[0], ny[1], ny[2]] };
}

/** Grid index (0..3) along local axis given by frame row (a, b, c) for root grid column C and row R. */
function localIndex(a: number, b: number, C: number, R: number): number {
  if (a === 1) return C;
  if (a === -1) return 3 - C;
  if (b === 1) return R;
  return 3 - R;
}

/** Corner (0..3 as (0,0),(1,0),(1,1),(0,1)) of the root-oriented square that local corner `lc` is. */
function rootCorner(F: Frame, lc: number): number {
  const L = [[0, 0], [1, 0], [1, 1], [0, 1]];
  for (let rc = 0; rc < 4; rc++) {
    const [x, y] = applyFrame(F, L[rc][0], L[rc][1]);
    if (Math.abs(x - L[lc][0]) < 1e-9 && Math.abs(y - L[lc][1]) < 1e-9) return rc;
  }
  throw new Error('frame is not a rotation of the square');
}

/** Subdominant eigenvalue of the smooth Catmull-Clark rule at interior valence n. */
export function subdominantEigenvalue(n: number): number {
  const th = (2 * Math.PI) / n;
  return (5 + Math.cos(th) + Math.cos(th / 2) * Math.sqrt(2 * (9 + Math.cos(th)))) / 16;
}

const dist = (a: number[], b: number[]): number => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

/**
 * Radial blend exponent where no closed form applies (creases, corners, darts, boundaries): how
 * fast the surface closes in on the vertex per level, measured on the current geometry from the
 * limit of the face's far corner at this level and at the next.
 */
function measuredExponent(L: Level, v: number, lc: number): number | null {
  try {
    const m = L.he;
    const a0 = m.faceOffsets[0];
    const far0 = m.faceIndices[a0 + ((lc + 2) % 4)];
    const P = vertexLimit(L, v, 0).P;
    const d0 = dist(vertexLimit(L, far0, 0).P, P);
    const R = refine(L);
    // Child of corner lc of face 0 is child face a0 + lc: [V(v), E, F, E'], its far corner F.
    const child = a0 + lc;
    const far1 = R.he.faceIndices[R.he.faceOffsets[child] + 2];
    const sub = extractFaces(R, faceNeighbourhood(R.he, child));
    let lf = 0;
    while (sub.vmap[lf] !== far1) lf++;
    const d1 = dist(vertexLimit(sub.level, lf, 0).P, P);
    if (!(d0 > 0 && d1 > 0)) return null;
    const a = Math.log2(d0 / d1);
    return a > 0.05 && a < 8 ? a : null;
  } catch {
    return null;
  }
}

class Builder {
  nodes: number[] = [];
  alpha: number[] = [];
  /** Control point stencils: per point, a list of (cage vertex, weight). */
  ctrl: { v: number[]; w: number[] }[] = [];
  patchCount = 0;
  unresolvedCount = 0;
  pendingLimits: { node: number; stencil: Float64Array; support: Int32Array }[] = [];

  constructor(readonly maxDepth: number) {}

  allocNodes(n: number): number {
    const at = this.nodes.length / 4;
    for (let i = 0; i < 4 * n; i++) this.nodes.push(0);
    for (let i = 0; i < n; i++) this.alpha.push(0);
    return at;
  }

  addPoints(stencil: Float64Array, S: number, support: Int32Array, count: number): number {
    const base = this.ctrl.length;
    for (let p = 0; p < count; p++) {
      const v: number[] = [], w: number[] = [];
      for (let j = 0; j < S; j++) {
        const x = stencil[p * S + j];
        if (x !== 0) { v.push(support[j]); w.push(x); }
      }
      this.ctrl.push({ v, w });
    }
    return base;
  }

  /** Fill node `at` for level s (face 0) in frame F. */
  build(at: number, s: SLevel, S: number, support: Int32Array, F: Frame, depth: number, kind: number): void {
    const L = s.lvl;
    const regular = isRegularFace(L, 0) && !L.hole[0] && gatherPatch(L, 0) !== null;
    if (regular) {
      const local = onStencils(s, S, 16, (l) => gatherPatch(l, 0)!);
      const oriented = new Float64Array(16 * S);
      for (let R = 0; R < 4; R++) {
        for (let C = 0; C < 4; C++) {
          const col = localIndex(F[0], F[1], C, R), row = localIndex(F[3], F[4], C, R);
          oriented.set(local.subarray((4 * row + col) * S, (4 * row + col + 1) * S), (4 * R + C) * S);
        }
      }
      // f32 precision: point 5 (the patch's corner (0,0)) is stored absolute, the other 15 as
      // offsets from it (difference stencils, formed in f64), so small deep patches keep their
      // shape to f32's relative precision instead of its absolute one.
      for (let i = 0; i < 16; i++) {
        if (i === ANCHOR) continue;
        for (let j = 0; j < S; j++) oriented[i * S + j] -= oriented[ANCHOR * S + j];
      }
      const base = this.addPoints(oriented, S, support, 16);
      this.nodes[4 * at] = NODE_PATCH | (kind << 4);
      this.nodes[4 * at + 1] = base;
      this.patchCount++;
      return;
    }
    // Which corners are irregular (and is a crease involved)?
    const m = L.he;
    const a0 = m.faceOffsets[0];
    let creased = false;
    const irregular: number[] = [];
    for (let j = 0; j < 4; j++) {
      const v = m.faceIndices[a0 + j];
      if (!isRegularVertex(m, v, L.edgeSharp, L.vertSharp, isBoundaryVertex(m, v))) irregular.push(j);
      if (L.vertSharp[v] > 0) creased = true;
      for (let k = m.vertEdgeOffsets[v]; k < m.vertEdgeOffsets[v + 1]; k++) {
        const e = m.vertEdges[k];
        if (L.edgeSharp[e] > 0 && m.edgeFaceCount[e] === 2) creased = true;
      }
    }
    const childKind = kind === PatchKind.Regular || kind === PatchKind.IrregularQuad ? (creased ? PatchKind.Crease : PatchKind.IrregularQuad) : kind;
    if (depth >= this.maxDepth || irregular.length === 0 /* hole or a face the reference cannot gather */) {
      const lc = irregular.length ? irregular[0] : 0;
      const v = m.faceIndices[a0 + lc];
      const lim = onStencils(s, S, 3, (l) => {
        const r = vertexLimit(l, v, 0);
        return [...r.P, ...r.lead, ...r.trail];
      });
      const base = this.addPoints(lim, S, support, 3);
      // Radial blend exponent: α = −log2 λ at smooth interior vertices, 1 elsewhere.
      let alpha = 1;
      let smoothEV = 0;
      const nE = m.vertEdgeOffsets[v + 1] - m.vertEdgeOffsets[v];
      const nF = m.vertHeOffsets[v + 1] - m.vertHeOffsets[v];
      let sharp = L.vertSharp[v] > 0;
      for (let k = m.vertEdgeOffsets[v]; k < m.vertEdgeOffsets[v + 1]; k++) if (L.edgeSharp[m.vertEdges[k]] > 0) sharp = true;
      if (!sharp && nE === nF && nE >= 3) alpha = -Math.log2(subdominantEigenvalue(nE));
      else alpha = measuredExponent(L, v, lc) ?? 1;
      if (!sharp && nE === nF && nE >= 3) smoothEV = 1;
      const rc = rootCorner(F, lc);
      this.nodes[4 * at] = NODE_UNRESOLVED | (rc << 2) | (childKind << 4) | (smoothEV << 7) | (Math.min(Math.round(alpha * 4096), 0xffff) << 8);
      this.nodes[4 * at + 1] = base;
      this.nodes[4 * at + 2] = NO_NODE;
      this.nodes[4 * at + 3] = NO_NODE;
      this.alpha[at] = Math.round(alpha * 4096) / 4096;
      this.unresolvedCount++;
      return;
    }
    const refined = refineS(s, S);
    const first = this.allocNodes(4);
    this.nodes[4 * at] = NODE_INTERNAL;
    this.nodes[4 * at + 1] = first;
    for (let J = 0; J < 2; J++) {
      for (let I = 0; I < 2; I++) {
        const { c, frame } = childFrame(F, I, J);
        const child = extractS(refined, S, faceNeighbourhood(refined.lvl.he, c));
        this.build(first + I + 2 * J, child, S, support, frame, depth + 1, childKind);
      }
    }
    // Siblings of unresolved children: the quadrant across the edge opposite the irregular corner.
    for (let J = 0; J < 2; J++) {
      for (let I = 0; I < 2; I++) {
        const n = first + I + 2 * J;
        if ((this.nodes[4 * n] & 3) !== NODE_UNRESOLVED) continue;
        const rc = (this.nodes[4 * n] >> 2) & 3;
        const cx = rc === 1 || rc === 2 ? 1 : 0, cy = rc >= 2 ? 1 : 0;
        if (cx === I) this.nodes[4 * n + 2] = first + (1 - I) + 2 * J;
        if (cy === J) this.nodes[4 * n + 3] = first + I + 2 * (1 - J);
      }
    }
  }
}

/** Build the quadtrees and stencils of a cage (its prepared triangulation gives the triangle order). */
export function buildCatmullClark(cage: Cage, prepared: PreparedMesh, opts: CatmullClarkOptions = {}): CatmullClarkData {
  const options: SubdivOptions = opts.subdiv ?? { ...DEFAULT_OPTIONS, ...cage.fileOptions };
  const maxDepth = opts.maxDepth ?? DEFAULT_MAX_DEPTH;
  const topo = buildTopology(cage);
  const level0 = levelFromCage(cage, topo, options);
  const cls = classify(topo, computeSharpness(cage, topo, options));
  const B = new Builder(maxDepth);
  const nF = topo.nFaces;
  const faceRoot = new Int32Array(nF).fill(-1);
  const faceKindOf = new Uint8Array(nF);

  for (let f = 0; f < nF; f++) {
    if (level0.hole[f]) continue;
    const n = topo.faceOffsets[f + 1] - topo.faceOffsets[f];
    const fk = cls.faceKind[f];
    const kind = fk === FaceKind.Regular ? PatchKind.Regular
      : fk === FaceKind.QuadIrregular ? ((cls.faceFlags[f] & 3) !== 0 ? PatchKind.Crease : PatchKind.IrregularQuad)
        : PatchKind.Triangle;
    faceKindOf[f] = kind;
    const { level, vmap } = extractFaces(level0, faceNeighbourhood(level0.he, f));
    const S = vmap.length;
    const W = new Float64Array(S * S);
    for (let i = 0; i < S; i++) W[i * S + i] = 1;
    const base: SLevel = { lvl: level, W };
    if (n === 4) {
      const at = B.allocNodes(1);
      faceRoot[f] = at;
      B.build(at, base, S, vmap, IDENTITY, 0, kind);
    } else {
      const refined = refineS(base, S);
      const first = B.allocNodes(n);
      faceRoot[f] = first;
      for (let k = 0; k < n; k++) {
        const sub = extractS(refined, S, faceNeighbourhood(refined.lvl.he, k));
        B.build(first + k, sub, S, vmap, IDENTITY, 0, kind);
      }
    }
  }
  const nodeCount = B.nodes.length / 4;

  // Cage vertex limits (P, lead, trail) for the factor rule and the flat baseline.
  const vertexLimitBase = B.ctrl.length;
  const nV = topo.nVerts;
  for (let v = 0; v < nV; v++) {
    if (topo.vertHeOffsets[v + 1] === topo.vertHeOffsets[v]) {
      B.ctrl.push({ v: [v], w: [1] }, { v: [], w: [] }, { v: [], w: [] });
      continue;
    }
    const { level, vmap } = extractFaces(level0, vertexFaces(level0.he, v));
    const S = vmap.length;
    const W = new Float64Array(S * S);
    for (let i = 0; i < S; i++) W[i * S + i] = 1;
    let lv = 0;
    while (vmap[lv] !== v) lv++;
    const lim = onStencils({ lvl: level, W }, S, 3, (l) => {
      const r = vertexLimit(l, lv, 0);
      return [...r.P, ...r.lead, ...r.trail];
    });
    B.addPoints(lim, S, vmap, 3);
  }

  // Triangles → roots.
  const nT = prepared.triangleCount;
  const triRoot = new Uint32Array(3 * nT);
  const polyAt = new Map<number, number>();
  const poly: number[] = [];
  const triKind = new Uint8Array(nT);
  for (let t = 0; t < nT; t++) {
    const f = prepared.triFace[t];
    const start = cage.faceOffsets[f];
    const n = cage.faceOffsets[f + 1] - start;
    let k = -1;
    for (let j = 1; j < n - 1; j++) if (cage.faceIndices[start + j] === prepared.triVerts[3 * t + 1]) k = j;
    if (k < 0 || cage.faceIndices[start] !== prepared.triVerts[3 * t]) throw new Error(`triangle ${t} is not a fan triangle of face ${f}`);
    triRoot[3 * t] = faceRoot[f];
    triRoot[3 * t + 1] = n | (k << 8);
    if (n !== 4) {
      let at = polyAt.get(n);
      if (at === undefined) {
        polyAt.set(n, (at = poly.length / 2));
        for (let j = 0; j < n; j++) poly.push(Math.cos((2 * Math.PI * j) / n), Math.sin((2 * Math.PI * j) / n));
      }
      triRoot[3 * t + 2] = at;
    }
    triKind[t] = faceKindOf[f];
  }

  // Stencils, CSR.
  const rows = new Uint32Array(B.ctrl.length + 1);
  let total = 0;
  B.ctrl.forEach((c, i) => {
    rows[i] = total;
    total += c.v.length;
  });
  rows[B.ctrl.length] = total;
  const entryVertex = new Uint32Array(total);
  const entryWeight = new Float32Array(total);
  let e = 0;
  for (const c of B.ctrl) {
    for (let j = 0; j < c.v.length; j++) {
      entryVertex[e] = c.v[j];
      entryWeight[e] = c.w[j];
      e++;
    }
  }
  const nodes = Uint32Array.from(B.nodes);
  const offTri = 0, offPoly = offTri + triRoot.length, offNodes = offPoly + poly.length, offRows = offNodes + nodes.length, offEntries = offRows + rows.length;
  const words = new Uint32Array(offEntries + 2 * total);
  words.set(triRoot, offTri);
  words.set(new Uint32Array(Float32Array.from(poly).buffer), offPoly);
  words.set(nodes, offNodes);
  words.set(rows, offRows);
  const ev = new Uint32Array(entryWeight.buffer);
  for (let i = 0; i < total; i++) {
    words[offEntries + 2 * i] = entryVertex[i];
    words[offEntries + 2 * i + 1] = ev[i];
  }
  return {
    words, offTri, offPoly, offNodes, offRows, offEntries, nodeCount, ctrlCount: B.ctrl.length, vertexLimitBase,
    patchCount: B.patchCount, unresolvedCount: B.unresolvedCount, maxDepth, triKind,
    nodes, alpha: Float32Array.from(B.alpha), rows, entryVertex, entryWeight, triRoot, vertexCount: nV,
  };
}

export { SHARPNESS_INFINITE };
