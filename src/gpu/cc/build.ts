/**
 * Catmull-Clark for the compute tessellator: the CPU half, TOPOLOGY ONLY (Hable's Part 3). No
 * positions, no weights, no per-face matrices: what is prepared here is which points exist, by
 * which rule each is made, and which points each piece of surface reads. Linear in the cage.
 * The GPU (wgsl/cc/build.wgsl) makes every point from the current cage every frame; the emit
 * passes evaluate (wgsl/cc/surface.wgsl).
 *
 * 1. Levels. Uniform refinement topology of the whole cage, levels 1..G, G as small as the
 *    cage allows (0 for an all-regular quad cage, 1 with extraordinary vertices, 2 with
 *    triangles or n-gons, more only where semi-sharp creases need to decay and are not single
 *    creases: see below). Level
 *    L+1 numbers its points [vertex points | edge points | face points] of level L (a vertex
 *    keeps its index at every deeper level); child face j of face f is half-edge
 *    faceOffsets[f]+j, [V(c_j), E(c_j c_j+1), F, E(c_j-1 c_j)]. Sharpness decays by notes §1.4.
 *    Each new point carries a RULE (2 words: kind and counts, first input) and its inputs
 *    (point indices): face point (N corners), edge point (ends + the two new face points;
 *    sharpness s: smooth, or after the inputs when not 0: crease, blend), vertex point (v, far
 *    ends of its edges, its new face points; parent rule, child rule, and when either is not
 *    smooth, after the inputs: the two crease edges and the transitional weight W in f32 as
 *    OpenSubdiv computes it).
 * 2. Fans. A vertex x of level s is a fan centre ("eligible") when every point of its 2-ring
 *    other than x obeys the regular valence-4 masks: its faces are quads, its incident edges
 *    and its own sharpness are 0 or infinite, each neighbour (1,0) is a valence-4 vertex
 *    whose only sharp edges are the two halves of the axis (or a valence-3 boundary vertex on
 *    a boundary axis) and each diagonal (1,1) is a smooth interior valence-4 vertex. Then
 *    (notes §6.2) one refinement step of the fan reads only the axis sharpness and the
 *    centre's rule: every other point touched is a face point, an edge point of an edge made
 *    inside a face (sharpness 0), or the vertex point of (1,0) / (1,1) above; and after one
 *    step the new (1,0), (1,1) are again of that kind. So the slice kernel is exact at every
 *    depth for boundaries, infinitely sharp creases into the EV, darts and corners alike.
 *    Semi-sharp values never reach a fan: a vertex is eligible only once they have decayed,
 *    which the uniform levels do (exactly, with OpenSubdiv's transitions).
 * 3. Regions. Face f is split to the smallest depth d at which each of its level-d descendants
 *    is a regular patch (isRegularVertex at its 4 corners: smooth, boundary, infinitely sharp
 *    phantoms), a SINGLE-CREASE patch, or has an eligible fan centre at a corner (an EV SECTOR
 *    region; its fan may start at a coarser level s ≤ d: offset d − s). d = 0 for regular
 *    quads (1 region), 1 for quads at an EV (4), 2 where triangles are involved (16 per quad,
 *    12 per triangle), as in the talk's table, and deeper only where semi-sharp creases fail
 *    the single-crease test. A single-crease patch (singleCrease; notes §3.4, OpenSubdiv's
 *    isSingleCreasePatch conditions): a quad whose 4 corners are interior valence-4 vertices
 *    of quads without vertex sharpness, whose only sharp edges at the corners are the 3
 *    collinear edges A'A, AB, BB' of one side AB, all of one semi-sharp σ. Its limit is the
 *    closed-form crease basis across the crease times the cubic B-spline along it, exact for
 *    integer and fractional σ, so such faces stop at depth 0 (1 at an EV) with no level
 *    refined for them: its 16 indices are gathered in the face's frame turned so that AB is
 *    the frame's x = 0 side (grid column 1), rot composed accordingly, and σ follows them.
 *    Likewise a cage vertex on a straight semi-sharp crease (two opposite edges of one σ, the
 *    rest smooth, valence 4) takes its limit from the closed form at the patch corner (its 3×3
 *    neighbourhood and σ; creaseVertexGrid) instead of a fan at the level where σ has decayed.
 *
 * Limits (honest): where a semi-sharp crease fails the single-crease test (it ends at a dart or
 * a boundary, meets another crease or a corner, or runs into an extraordinary vertex) its
 * sharpness still decays by UNIFORM levels of the whole cage, ceil(σ) of them (sharpness ≥ 7
 * needs more than MAX_LEVEL = 6 and is refused with a message, as are vertices of valence > 64,
 * more than a workgroup, and Chaikin creasing). catmark_pawn's crease loops are all single-crease
 * (1 level, ~0.5 KB per face), but catmark_bishop and _car have σ ≈ 5 creases through valence-5
 * vertices and still take 6 levels (hundreds of KB per face), and the project's creased-box's
 * creases all end at the cube's corners (3 levels). The rest of the design is what fixes
 * those: semi-sharp axes decaying inside the slice kernel (fans eligible at once) and levels
 * refined only round the faces that need them.
 *
 * GPU point space (f32 xyz in cageBuf; index p < ccCageVerts, the cage's vertex count: the cage
 * positions; p ≥ ccCageVerts at offPoints + 3(p − ccCageVerts)):
 *   [cage | level 1 | … | level G | fan slices | fan limits]
 *   slices of fan F (depth D, ns threads = sectors + 1 on a boundary), all as OFFSETS from the
 *     fan's anchor (its centre at level s: f32 precision of deep levels, notes §6.7):
 *       centres   D points, the centre after step k = 1..D at slot k − 1;
 *       rings     the fan's 1-ring, (1,0) and (1,1) of each sector at slot 2i, 2i + 1, after
 *                 the steps k ≡ D (mod 2) only (ceil(D/2) rings; step D's is always there),
 *                 ring of step k at D + ((k − 1 − ((D + 1) mod 2)) / 2)·2·ns.
 *     Why so little: the slice kernel computes the whole 2-ring of every step in workgroup
 *     memory, but what the evaluator cannot redo cheaply is only what spreads round the fan:
 *     the centre (it reads every sector) and the 1-ring (each point reads its two neighbour
 *     sectors, so a local step of one sector would need ever more sectors). Given those, one
 *     sector's own outer points (a = 2 or b = 2) at step L follow by L local steps from the start
 *     level that read only sectors i−1, i, i+1 (wgsl/cc/surface.wgsl), and a ring of an odd
 *     step follows from the stored ring before it by one step. A sector then costs 4 points
 *     every other step instead of 6 every step: a third of the slices' memory at 2/6 · 1/2
 *     (imrod, all triangles: 2.7 KB of slices per face before, under 0.6 KB now).
 *   Then the limits: P (absolute), T1, T2 (the vertex's: the factor rule, the flat baseline);
 *     then, at a crease or corner centre (rule not smooth), T1, T2 of each face i < n at
 *     3 + 2i, 4 + 2i: an infinitely sharp crease splits the tangent plane into sectors (one per
 *     span of faces between two sharp edges, one per face at a corner), and a face's corner
 *     takes the normal of its own (src/gpu/tess/prepare.ts splitCreases outputs a vertex once per
 *     sector). As the CPU reference (src/subdiv/limit.ts vertexLimit for that face).
 *
 * Static words (u32, appended to the tessellator's static buffer; offsets below are relative):
 *   tri      3 per prepared triangle: first region of the face, CC_TRI_WORD (n, fan k, centred:
 *            corners (centre, k, k + 1) else (0, k, k + 1), depth counted inside the quad or
 *            inside the sub-face), first corner in `poly`
 *   poly     regular n-gon corners (cos, sin as f32 bits, f64 on the CPU)
 *   regions  2 per region, region (i, j) of sub-face k at base + k·4^dd + j·2^dd + i:
 *            w0 = CC_REGION_WORD (src/gpu/cc/words.ts): kind (1 patch, 2 sector) [0,2), rot
 *                 [2,4), phantom mask [4,8), offset [8,12), sector [12,18), crease [18]
 *                 (single-crease patch), patch kind [24,26);  w1 = word offset in `patchIdx`
 *                 of the patch's 16 indices (row-major, row ~ y of the region's own frame) or
 *                 fan id (sector).
 *            rot r: the region's frame is rot_r of the root square, rot_1(x,y) = (y, 1−x).
 *   patchIdx per patch 16 point indices, then for a single-crease patch σ (f32 bits; the
 *            crease on the frame's x = 0 side); per crease vertex (vfan) 9 point indices of
 *            its 3×3 neighbourhood (3a + b, a across the crease) and σ
 *   fans     8 per fan: ns | n << 8 | boundary << 16 | rule << 17 | D << 20; anchor;
 *            slice base; sector base; alpha (f32); limit base; ia | ib << 8; cos base
 *   sectors  7 per sector (ns per fan): axis-infinite flag, (1,0) (2,0) (1,1) (2,1) (1,2) (2,2)
 *            at level s; the boundary pseudo-sector (axis n) has only (1,0), (2,0)
 *   threads  64 per slice workgroup: fan | sector << 24, or ~0 (idle)
 *   cos      per valence n used by a smooth fan: cos(2πi/n), i < n, then 1/(4λ−1)
 *   rules    2 per point of levels ≥ 1: w0, first input. w0 = kind (0 face, 1 edge, 2 vertex) |
 *            face: n << 8; edge: sharp << 2 | n << 8 (n = 2 on a boundary, else 4);
 *            vertex: parent rule << 2 | child rule << 4 | edges << 8 | faces << 20
 *   inputs   point indices read by the rules, each rule's followed by its parameters (edge:
 *            sharpness f32 if flagged; vertex with a non-smooth rule: ia | ib << 16, W f32)
 *   vfan     per prepared vertex (the cage's, then the face centres of prepare.ts),
 *            CC_VERTEX_LIMIT_WORD: its fan (limit position and normal for the factor rule), or
 *            (crease bit) the word offset of its crease record in patchIdx, or ~0
 */
import {
  type Cage,
  type HalfEdges,
  type SubdivOptions,
  DEFAULT_OPTIONS,
  FaceKind,
  SHARPNESS_INFINITE,
  buildTopology,
  classify,
  computeSharpness,
  isRegularVertex,
  vertexAdjacency,
  vertexRing,
} from '../../mesh/index.ts';
import { fannedRoundCentre, type PreparedMesh } from '../tess/prepare.ts';
import { NO_OWNER, OWNER_WORD } from '../contract/tess.ts';
import { CC_FAN_WORD, CC_PAIR_WORD, CC_REGION_WORD, CC_RULE_WORD, CC_THREAD_WORD, CC_TRI_WORD, CC_VERTEX_LIMIT_WORD } from './words.ts';

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

export const REGION_PATCH = 1;
export const REGION_SECTOR = 2;
export const RULE_FACE = 0;
export const RULE_EDGE = 1;
export const RULE_VERTEX = 2;
export const VRULE_SMOOTH = 0;
export const VRULE_CREASE = 1;
export const VRULE_CORNER = 2;
export const NONE = 0xffffffff;
export const WORKGROUP = 64;

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
/** Deepest uniform level tried before a face is declared unsupported. */
const MAX_LEVEL = 6;

export interface CatmullClarkOptions {
  /** Subdivision options (default: the cage file's, over OpenSubdiv's defaults). */
  subdiv?: SubdivOptions;
}

export interface CatmullClarkData {
  words: Uint32Array;
  offTri: number;
  offPoly: number;
  offRegions: number;
  offPatchIdx: number;
  offFans: number;
  offSectors: number;
  offThreads: number;
  offCos: number;
  offRules: number;
  offInputs: number;
  offVertexFan: number;
  /** Points of the levels ≥ 1, fan slices and limits (the cage's vertices come first in the point space). */
  pointCount: number;
  /** Global point index ranges for the level dispatches: per level [faceFirst, faceCount, veFirst, veCount]. */
  levelRanges: [number, number, number, number][];
  fanCount: number;
  sliceWorkgroups: number;
  maxDepth: number;
  regionCount: number;
  patchCount: number;
  /** Of the patches, single-crease ones (one semi-sharp crease on a side, closed form). */
  singleCreaseCount: number;
  sectorRegionCount: number;
  levels: number;
  /** Per prepared triangle: the face's patch kind (for colours). */
  triKind: Uint8Array;
  /** Per cage face: region depth (quads) or depth inside its sub-faces + 1 (n-gons); -1 holes. */
  faceDepth: Int8Array;
  /** Per cage face: its first region (-1 holes); the face has 4^d regions (n·4^(d−1) for n-gons). */
  faceRegion: Int32Array;
  /** Host copies for the CPU side of the checks (which points are in a blended square). */
  regions: Uint32Array;
  fans: Uint32Array;
  triRegion: Uint32Array;
  /** The cage's vertex count: points p below it are the cage's vertices (the point space's base). */
  cageVertexCount: number;
  /** Bytes of GPU subdivision data: static words + points (12 B each). */
  gpuBytes: number;
}

interface Level {
  he: HalfEdges;
  edgeSharp: Float64Array;
  vertSharp: Float64Array;
  hole: Uint8Array;
  boundary: Uint8Array;
  /** Global point index of this level's vertex 0. */
  base: number;
  regular: Int8Array; // -1 unknown
  eligible: Int8Array; // -1 unknown
}

const dec = (s: number): number => (s <= 1 ? 0 : s >= SHARPNESS_INFINITE ? SHARPNESS_INFINITE : Math.fround(s - 1));
const INF = SHARPNESS_INFINITE;

function makeLevel(he: HalfEdges, edgeSharp: Float64Array, vertSharp: Float64Array, hole: Uint8Array, base: number): Level {
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
  };
}

function vertexRuleOf(nSharp: number, vs: number): number {
  if (vs > 0 || nSharp >= 3) return VRULE_CORNER;
  return nSharp === 2 ? VRULE_CREASE : VRULE_SMOOTH; // 0: smooth, 1: dart (smooth mask)
}

/** Growable u32 list. */
class U32 {
  a = new Uint32Array(1024);
  n = 0;
  push(x: number): void {
    if (this.n === this.a.length) {
      const b = new Uint32Array(2 * this.a.length);
      b.set(this.a);
      this.a = b;
    }
    this.a[this.n++] = x >>> 0;
  }
  get view(): Uint32Array {
    return this.a.subarray(0, this.n);
  }
}

const f32bits = (x: number): number => new Uint32Array(Float32Array.of(x).buffer)[0];

/** Refine level L's topology once: the rules of level L+1's points, and level L+1. */
function refineLevel(L: Level, rules: U32, inputs: U32): Level {
  const m = L.he;
  const nV = m.nVerts,
    nE = m.nEdges,
    nF = m.nFaces;
  const base1 = L.base + nV;
  const fBase = base1 + nV + nE,
    vBase = L.base;
  // Vertex points.
  for (let v = 0; v < nV; v++) {
    const e0 = m.vertEdgeOffsets[v],
      e1 = m.vertEdgeOffsets[v + 1];
    const h0 = m.vertHeOffsets[v],
      h1 = m.vertHeOffsets[v + 1];
    const first = inputs.n;
    inputs.push(vBase + v);
    let nSharp = 0,
      nSharpChild = 0,
      ia = 0,
      ib = 0,
      ca = 0,
      cb = 0;
    let tSum = 0,
      tCount = 0;
    const vs = L.vertSharp[v];
    if (vs > 0 && dec(vs) === 0) {
      tSum = Math.fround(vs);
      tCount = 1;
    }
    for (let k = e0; k < e1; k++) {
      const e = m.vertEdges[k];
      inputs.push(vBase + m.edgeVerts[2 * e] + m.edgeVerts[2 * e + 1] - v);
      const s = L.edgeSharp[e];
      if (s > 0) {
        if (nSharp === 0) ia = k - e0;
        else if (nSharp === 1) ib = k - e0;
        nSharp++;
      }
      if (dec(s) > 0) {
        if (nSharpChild === 0) ca = k - e0;
        else if (nSharpChild === 1) cb = k - e0;
        nSharpChild++;
      }
      if (s > 0 && dec(s) === 0) {
        tSum = Math.fround(tSum + s);
        tCount++;
      }
    }
    for (let k = h0; k < h1; k++) inputs.push(fBase + m.heFace[m.vertHe[k]]);
    const pr = vertexRuleOf(nSharp, vs);
    let cr = vertexRuleOf(nSharpChild, dec(vs));
    let W = 1;
    if ((pr === VRULE_CREASE || pr === VRULE_CORNER) && cr !== pr) {
      W = tCount ? Math.min(1, Math.fround(tSum / tCount)) : 0;
    } else cr = pr;
    // The crease pair: the parent's if it is a crease, else the child's.
    if (pr !== VRULE_CREASE) {
      ia = ca;
      ib = cb;
    }
    if (e1 - e0 >= 1 << 12 || h1 - h0 >= 1 << 12) throw new Error(`vertex of valence ${e1 - e0} is not supported`);
    rules.push(CC_RULE_WORD.pack({ kind: RULE_VERTEX, parent: pr, child: cr, sharp: 0, count: e1 - e0, faces: h1 - h0 }));
    rules.push(first);
    // A sharp vertex (either rule not smooth) carries its crease pair and W after its inputs.
    if (pr !== VRULE_SMOOTH || cr !== VRULE_SMOOTH) {
      inputs.push(CC_PAIR_WORD.pack({ a: ia, b: ib }));
      inputs.push(f32bits(W));
    }
  }
  // Edge points.
  for (let e = 0; e < nE; e++) {
    const first = inputs.n;
    inputs.push(vBase + m.edgeVerts[2 * e]);
    inputs.push(vBase + m.edgeVerts[2 * e + 1]);
    let n = 2;
    if (m.edgeFaceCount[e] === 2) {
      const h = m.edgeHe[e];
      inputs.push(fBase + m.heFace[h]);
      inputs.push(fBase + m.heFace[m.heTwin[h]]);
      n = 4;
    }
    // An interior edge with sharpness carries it after its inputs (flag bit 2).
    const sharpEdge = n === 4 && L.edgeSharp[e] !== 0;
    if (sharpEdge) inputs.push(f32bits(L.edgeSharp[e]));
    rules.push(CC_RULE_WORD.pack({ kind: RULE_EDGE, parent: 0, child: 0, sharp: sharpEdge, count: n, faces: 0 }));
    rules.push(first);
  }
  // Face points.
  for (let f = 0; f < nF; f++) {
    const a = m.faceOffsets[f],
      b = m.faceOffsets[f + 1];
    rules.push(CC_RULE_WORD.pack({ kind: RULE_FACE, parent: 0, child: 0, sharp: 0, count: b - a, faces: 0 }));
    rules.push(inputs.n);
    for (let h = a; h < b; h++) inputs.push(vBase + m.faceIndices[h]);
  }
  // Level L+1 topology.
  const nHe = m.faceIndices.length;
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
    if (lo < nV && hi >= nV && hi < nV + nE) edgeSharp[e] = dec(L.edgeSharp[hi - nV]);
  }
  const vertSharp = new Float64Array(nV1);
  for (let v = 0; v < nV; v++) vertSharp[v] = dec(L.vertSharp[v]);
  return makeLevel(he, edgeSharp, vertSharp, hole, base1);
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
  return {
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
  };
}

function isRegular(L: Level, v: number): boolean {
  if (L.regular[v] < 0) L.regular[v] = isRegularVertex(L.he, v, L.edgeSharp, L.vertSharp, !!L.boundary[v]) ? 1 : 0;
  return L.regular[v] === 1;
}

const sharp0orInf = (s: number) => s === 0 || s >= INF;

/** Is x a fan centre at this level (see the header: the slice kernel is exact round it)? */
function isEligible(L: Level, x: number): boolean {
  if (L.eligible[x] >= 0) return L.eligible[x] === 1;
  const r = eligible(L, x);
  L.eligible[x] = r ? 1 : 0;
  return r;
}

function isQuadHe(m: HalfEdges, h: number): boolean {
  return m.faceOffsets[m.heFace[h] + 1] - m.faceOffsets[m.heFace[h]] === 4;
}

/** Is y a valid axis neighbour (1,0) of a fan centre along an axis of sharpness axisSharp? */
function axisOk(L: Level, y: number, axisSharp: number): boolean {
  const m = L.he;
  if (L.vertSharp[y] !== 0) return false;
  const nf = m.vertHeOffsets[y + 1] - m.vertHeOffsets[y],
    ne = m.vertEdgeOffsets[y + 1] - m.vertEdgeOffsets[y];
  for (let k = m.vertHeOffsets[y]; k < m.vertHeOffsets[y + 1]; k++) if (!isQuadHe(m, m.vertHe[k])) return false;
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
  if (!sharp0orInf(L.vertSharp[x])) return false;
  for (let k = m.vertEdgeOffsets[x]; k < m.vertEdgeOffsets[x + 1]; k++) if (!sharp0orInf(L.edgeSharp[m.vertEdges[k]])) return false;
  for (let k = m.vertHeOffsets[x]; k < m.vertHeOffsets[x + 1]; k++) if (!isQuadHe(m, m.vertHe[k])) return false;
  const ring = vertexRing(m, x);
  if (!ring || ring.he.length === 0) return false;
  const n = ring.he.length;
  if (n + (ring.boundary ? 1 : 0) > WORKGROUP) return false;
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

// Sector coordinates of corner j of a quad in its own frame: (a, b) = rot_j(x, y).
const QUAD_OF_ROT: [number, number][] = [
  [0, 0],
  [1, 0],
  [1, 1],
  [0, 1],
];
const GRID_POS: [number, number][] = [
  [1, 1],
  [2, 1],
  [2, 2],
  [1, 2],
];
const AXES: [number, number, number, number][] = [
  [1, 0, 0, 1],
  [0, 1, -1, 0],
  [-1, 0, 0, -1],
  [0, -1, 1, 0],
];

function setGrid(grid: number[], c: number, r: number, v: number): void {
  if (c >= 0 && c < 4 && r >= 0 && r < 4) grid[4 * r + c] = v;
}

/**
 * The 16 point indices (global) of a regular level face g and its phantom mask, in the face's own
 * frame turned to start at corner `start` (its corner `start` at grid (1,1), the edge leaving it
 * along +x); null if a slot stays empty.
 */
function gatherPatch(L: Level, g: number, start = 0): { idx: number[]; mask: number } | null {
  const m = L.he;
  const a0 = m.faceOffsets[g];
  const grid = new Array<number>(16).fill(-1);
  let mask = 0;

  for (let j = 0; j < 4; j++) {
    const h = a0 + ((j + start) & 3);
    if (L.edgeSharp[m.heEdge[h]] >= INF) mask |= 1 << j;
    const [gc, gr] = GRID_POS[j];
    const [ax, ay, bx, by] = AXES[j];
    setGrid(grid, gc, gr, m.faceIndices[h]);
    const t1 = m.heTwin[m.hePrev[h]];
    if (t1 < 0) continue;
    setGrid(grid, gc + bx - ax, gr + by - ay, m.faceIndices[m.heNext[m.heNext[t1]]]);
    setGrid(grid, gc - ax, gr - ay, m.faceIndices[m.hePrev[t1]]);
    const t2 = m.heTwin[m.hePrev[t1]];
    if (t2 < 0) continue;
    setGrid(grid, gc - ax - bx, gr - ay - by, m.faceIndices[m.heNext[m.heNext[t2]]]);
    setGrid(grid, gc - bx, gr - by, m.faceIndices[m.hePrev[t2]]);
    const t3 = m.heTwin[m.hePrev[t2]];
    if (t3 < 0) continue;
    setGrid(grid, gc + ax - bx, gr + ay - by, m.faceIndices[m.heNext[m.heNext[t3]]]);
  }
  for (let r = 0; r < 4; r++) {
    for (let c = 0; c < 4; c++) {
      if (grid[4 * r + c] >= 0) continue;
      const covered = (r === 0 && mask & 1) || (c === 3 && mask & 2) || (r === 3 && mask & 4) || (c === 0 && mask & 8);
      if (!covered) return null;
      grid[4 * r + c] = m.faceIndices[a0]; // discarded by the phantom reflection
    }
  }
  return { idx: grid.map((v) => L.base + v), mask };
}

const semiSharp = (s: number): boolean => s > 0 && s < INF;

/** Is v an interior valence-4 vertex of quads (no holes round it) without vertex sharpness? */
function plainValence4(L: Level, v: number): boolean {
  const m = L.he;
  if (L.boundary[v] || L.vertSharp[v] !== 0) return false;
  if (m.vertHeOffsets[v + 1] - m.vertHeOffsets[v] !== 4 || m.vertEdgeOffsets[v + 1] - m.vertEdgeOffsets[v] !== 4) return false;
  for (let k = m.vertHeOffsets[v]; k < m.vertHeOffsets[v + 1]; k++) {
    const h = m.vertHe[k];
    if (!isQuadHe(m, h) || L.hole[m.heFace[h]]) return false;
  }
  return true;
}

/** Round an interior vertex: the half-edge leaving it after h (twin of the previous). */
const turnHe = (m: HalfEdges, h: number): number => m.heTwin[m.hePrev[h]];

/**
 * A single-crease patch (notes §3.4; OpenSubdiv's isSingleCreasePatch conditions): level face g
 * is a quad whose 4 corners are interior valence-4 vertices of quads without vertex sharpness,
 * and the only sharp edges at its corners are the 3 collinear edges A'A, AB, BB' of one of its
 * sides AB, all of the same semi-sharp σ. Then its limit is the tensor product of the cubic
 * B-spline along the crease and the closed-form 1D crease basis across it: only the rules of the
 * 4 corners and of the edges at them reach the sub-patches, and they stay of this kind as σ
 * decays. Returns the corner to start the patch's frame at (B: the crease AB becomes the frame's
 * x = 0 side, grid column 1) and σ; null if g is not such a face.
 */
function singleCrease(L: Level, g: number): { start: number; sigma: number } | null {
  const m = L.he;
  const a0 = m.faceOffsets[g];
  if (m.faceOffsets[g + 1] - a0 !== 4) return null;
  let side = -1;
  for (let j = 0; j < 4; j++) {
    if (!plainValence4(L, m.faceIndices[a0 + j])) return null;
    if (L.edgeSharp[m.heEdge[a0 + j]] !== 0) {
      if (side >= 0) return null;
      side = j;
    }
  }
  if (side < 0) return null;
  const h = a0 + side;
  const sigma = L.edgeSharp[m.heEdge[h]];
  if (!semiSharp(sigma)) return null;
  // The crease goes straight on through A and B: the edges opposite AB round A and round B.
  const ea = m.heEdge[turnHe(m, turnHe(m, h))];
  const eb = m.heEdge[turnHe(m, turnHe(m, m.heTwin[h]))];
  if (L.edgeSharp[ea] !== sigma || L.edgeSharp[eb] !== sigma) return null;
  const crease = [m.heEdge[h], ea, eb];
  for (let j = 0; j < 4; j++) {
    const v = m.faceIndices[a0 + j];
    for (let k = m.vertEdgeOffsets[v]; k < m.vertEdgeOffsets[v + 1]; k++) {
      const e = m.vertEdges[k];
      if (L.edgeSharp[e] !== 0 && !crease.includes(e)) return null;
    }
  }
  return { start: (side + 1) & 3, sigma };
}

/**
 * A vertex on a straight semi-sharp crease (two opposite edges of the same semi-sharp σ, the
 * other two smooth, an interior valence-4 vertex of quads, no vertex sharpness): its limit is
 * the corner of the single-crease patches round it, in closed form (wgsl/cc/build.wgsl
 * vlimits). Its 3×3 neighbourhood at 3a + b (global indices), a across the crease, b along it,
 * oriented as the faces (a toward the first ring neighbour, b toward the next: cross(∂a, ∂b) is
 * the surface normal); null if v is not such a vertex.
 */
function creaseVertexGrid(L: Level, v: number): { idx: number[]; sigma: number } | null {
  const m = L.he;
  if (!plainValence4(L, v)) return null;
  let h = m.vertHe[m.vertHeOffsets[v]];
  if (L.edgeSharp[m.heEdge[h]] !== 0) h = turnHe(m, h);
  const hs = [h, turnHe(m, h), turnHe(m, turnHe(m, h)), turnHe(m, turnHe(m, turnHe(m, h)))];
  const s = hs.map((x) => L.edgeSharp[m.heEdge[x]]);
  if (s[0] !== 0 || s[2] !== 0 || !semiSharp(s[1]) || s[3] !== s[1]) return null;
  const pos: [number, number][] = [
    [2, 1],
    [1, 2],
    [0, 1],
    [1, 0],
  ];
  const grid = new Array<number>(9).fill(-1);
  grid[4] = v;
  for (let k = 0; k < 4; k++) {
    const [a, b] = pos[k],
      [a2, b2] = pos[(k + 1) & 3];
    grid[3 * a + b] = m.faceIndices[m.heNext[hs[k]]];
    // Face k holds ring neighbours k and k + 1 (the next half-edge round v leaves to prev's start).
    grid[3 * (a + a2 - 1) + (b + b2 - 1)] = m.faceIndices[m.heNext[m.heNext[hs[k]]]];
  }
  return { idx: grid.map((x) => L.base + x), sigma: s[1] };
}

interface FanRec {
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
  /** Per thread: axis-infinite flag and 6 global point indices. */
  sectors: number[][];
  /** The level-s face of each sector. */
  ringFaces: number[];
}

/** Build the topology-only Catmull-Clark data of a cage (its prepared triangulation gives the triangle order). */
export function buildCatmullClark(cage: Cage, prepared: PreparedMesh, opts: CatmullClarkOptions = {}): CatmullClarkData {
  const options: SubdivOptions = opts.subdiv ?? { ...DEFAULT_OPTIONS, ...cage.fileOptions };
  if (options.creasing === 'chaikin') throw new Error('Chaikin creasing is not supported by the GPU path');
  const topo = buildTopology(cage);
  const sharp = computeSharpness(cage, topo, options);
  const cls = classify(topo, sharp);
  // A vertex's valence never changes under refinement, so one whose fan needs more threads
  // than a workgroup can never be a fan centre: say so now rather than "too many levels" later.
  for (let v = 0; v < topo.nVerts; v++) {
    const faces = topo.vertHeOffsets[v + 1] - topo.vertHeOffsets[v];
    if (faces + (topo.vertBoundary[v] ? 1 : 0) > WORKGROUP)
      throw new Error(
        `Catmull-Clark: vertex ${v + 1} has ${faces} faces, more than the ${WORKGROUP} threads of a slice workgroup (not supported)`,
      );
  }
  const nV0 = topo.nVerts;
  const levels: Level[] = [makeLevel(topo, sharp.edge, sharp.vertex, sharp.hole, 0)];
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
      throw new Error(
        `Catmull-Clark: a face needs more than ${MAX_LEVEL} levels of refinement (semi-sharp creases decay one level per unit of ` +
          `sharpness; this cage has sharpness up to ${+maxSemiSharp().toPrecision(3)}: not supported)`,
      );
    while (levels.length <= l) {
      const L = levels[levels.length - 1];
      const N = refineLevel(L, rules, inputs);
      const nV = L.he.nVerts,
        nE = L.he.nEdges,
        nF = L.he.nFaces;
      levelRanges.push([N.base + nV + nE, nF, N.base, nV + nE]);
      levels.push(N);
    }
    return levels[l];
  };

  // Fans, keyed by (start level, vertex).
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

  // Regions.
  const regionWords = new U32();
  const patchIdx = new U32();
  const faceRegion = new Int32Array(topo.nFaces).fill(-1);
  const faceDepth = new Int8Array(topo.nFaces).fill(-1);
  const faceKindOf = new Uint8Array(topo.nFaces);
  let patchCount = 0,
    singleCreaseCount = 0,
    sectorRegionCount = 0;
  type Desc = { g: number; k: number; i: number; j: number; r: number };
  for (let f = 0; f < topo.nFaces; f++) {
    if (sharp.hole[f]) continue;
    const N = topo.faceOffsets[f + 1] - topo.faceOffsets[f];
    const fk = cls.faceKind[f];
    const kind =
      fk === FaceKind.Regular
        ? PatchKind.Regular
        : fk === FaceKind.QuadIrregular
          ? (cls.faceFlags[f] & 3) !== 0
            ? PatchKind.Crease
            : PatchKind.IrregularQuad
          : PatchKind.Triangle;
    faceKindOf[f] = kind;
    // First depth worth trying: 0 for a quad (regular, or a sector of a fan eligible on the
    // cage); an n-gon's sub-faces are regions at level 1 only when its corners are smooth
    // interior valence-4 vertices (else the face point's fan is not eligible at level 1: its
    // diagonals are those corners).
    let d0 = N === 4 ? 0 : 1;
    if (N !== 4) {
      for (let h = topo.faceOffsets[f]; h < topo.faceOffsets[f + 1]; h++) {
        const v = topo.faceIndices[h];
        if (topo.valence[v] !== 4 || topo.vertBoundary[v]) d0 = 2;
      }
    }
    for (let d = d0; ; d++) {
      // Descendants at level d with their place in the root square (or sub-face k).
      let desc: Desc[] = N === 4 ? [{ g: f, k: 0, i: 0, j: 0, r: 0 }] : [];
      if (N !== 4) for (let k = 0; k < N; k++) desc.push({ g: topo.faceOffsets[f] + k, k, i: 0, j: 0, r: 0 });
      for (let l = N === 4 ? 0 : 1; l < d; l++) {
        const L = level(l);
        const next: Desc[] = [];
        for (const q of desc) {
          for (let c = 0; c < 4; c++) {
            const r = (q.r + c) & 3;
            next.push({ g: L.he.faceOffsets[q.g] + c, k: q.k, i: 2 * q.i + QUAD_OF_ROT[r][0], j: 2 * q.j + QUAD_OF_ROT[r][1], r });
          }
        }
        desc = next;
      }
      const L = level(d);
      const m = L.he;
      type Reg = { w0: number; w1: number; patch?: number[]; sigma?: number };
      const regs: Reg[] = [];
      let ok = true;
      for (const q of desc) {
        const a0 = m.faceOffsets[q.g];
        let irregular = -1,
          nIrr = 0;
        for (let c = 0; c < 4; c++)
          if (!isRegular(L, m.faceIndices[a0 + c])) {
            irregular = c;
            nIrr++;
          }
        const patchWord = (rot: number, mask: number, crease: boolean) =>
          CC_REGION_WORD.pack({ kind: REGION_PATCH, rot, mask, offset: 0, sector: 0, crease, patchKind: kind });
        if (nIrr === 0) {
          const p = gatherPatch(L, q.g);
          if (p) {
            regs.push({ w0: patchWord(q.r, p.mask, false), w1: 0, patch: p.idx });
            continue;
          }
        } else {
          // One semi-sharp crease along a side: a single-crease patch, turned so the crease is
          // its x = 0 side.
          const sc = singleCrease(L, q.g);
          const p = sc && gatherPatch(L, q.g, sc.start);
          if (sc && p && p.mask === 0) {
            regs.push({ w0: patchWord((q.r + sc.start) & 3, 0, true), w1: 0, patch: p.idx, sigma: sc.sigma });
            singleCreaseCount++;
            continue;
          }
        }
        // An EV sector: a corner that is (or descends from) an eligible fan centre.
        let found = false;
        for (let c = 0; c < 4 && !found; c++) {
          if (nIrr > 0 && c !== irregular) continue;
          const x = m.faceIndices[a0 + c];
          const s = fanStart(x, d);
          if (s < 0) continue;
          // Sector index: this face's ancestor at level s in x's ring. The face at level d
          // descends from the level-s face whose corner x it shares: walk up by child index.
          let g = q.g;
          for (let l = d; l > s; l--) g = levels[l - 1].he.heFace[g];
          const fan = getFan(s, x, Math.max(1, TOTAL_DEPTH - s));
          const sector = fans[fan].ringFaces.indexOf(g);
          if (sector < 0) throw new Error(`Catmull-Clark: face ${f} is not in the fan of its corner`);
          regs.push({
            w0: CC_REGION_WORD.pack({
              kind: REGION_SECTOR,
              rot: (q.r + c) & 3,
              mask: 0,
              offset: d - s,
              sector,
              crease: 0,
              patchKind: kind,
            }),
            w1: fan,
          });
          found = true;
        }
        if (!found) {
          ok = false;
          break;
        }
      }
      if (!ok) continue;
      const dd = N === 4 ? d : d - 1;
      const side = 1 << dd;
      const base = regionWords.n / 2;
      const order = new Array<Reg>(regs.length);
      desc.forEach((q, n) => {
        order[q.k * side * side + q.j * side + q.i] = regs[n];
      });
      for (const rg of order) {
        if (rg.patch) {
          regionWords.push(rg.w0);
          regionWords.push(patchIdx.n);
          for (const v of rg.patch) patchIdx.push(v);
          if (rg.sigma !== undefined) patchIdx.push(f32bits(rg.sigma));
          patchCount++;
        } else {
          regionWords.push(rg.w0);
          regionWords.push(rg.w1);
          sectorRegionCount++;
        }
      }
      faceRegion[f] = base;
      faceDepth[f] = d;
      break;
    }
  }

  // Every prepared vertex's limit (the factor rule, the flat baseline) comes from its fan, or on
  // a straight semi-sharp crease from the closed form (no level refined for it). A cage vertex
  // is x = v at level 0; a face's centre vertex (prepare.ts) is its face point, the level-1
  // vertex nV + nE + f (a vertex point keeps its index at every finer level).
  const vertexFan = new Uint32Array(prepared.vertexCount).fill(NONE);
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

  function makeFan(L: Level, l: number, x: number): FanRec {
    const m = L.he;
    const ring = vertexRing(m, x)!;
    const n = ring.he.length;
    const G = (v: number) => L.base + v;
    const fi = m.faceIndices,
      nx = m.heNext;
    const sectors: number[][] = [];
    let nInf = 0,
      ia = 0,
      ib = 0;
    for (let i = 0; i < n; i++) {
      const h = ring.he[i];
      const inf = L.edgeSharp[m.heEdge[h]] >= INF ? 1 : 0;
      if (inf) {
        if (nInf === 0) ia = i;
        else ib = i;
        nInf++;
      }
      const t = m.heTwin[nx[h]];
      const u = m.heTwin[nx[nx[nx[t]]]];
      sectors.push([inf, G(fi[nx[h]]), G(fi[nx[nx[t]]]), G(fi[nx[nx[h]]]), G(fi[nx[nx[nx[t]]]]), G(fi[nx[nx[nx[u]]]]), G(fi[nx[nx[u]]])]);
    }
    if (ring.boundary) {
      const hl = ring.he[n - 1];
      const w = m.heTwin[nx[nx[hl]]];
      sectors.push([1, G(fi[m.hePrev[hl]]), G(fi[m.hePrev[w]]), G(x), G(x), G(x), G(x)]);
      ib = n;
      nInf++;
    }
    const vs = L.vertSharp[x];
    const rule = vertexRuleOf(nInf, vs);
    const smoothInterior = !ring.boundary && nInf === 0 && vs === 0 && n >= 3;
    const inf = sectors.map((q) => q[0]);
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
      ringFaces: ring.he.map((h) => m.heFace[h]),
      alpha: smoothInterior ? -Math.log2(subdominantEigenvalue(n)) : ringExponent(n, ring.boundary, rule, ia, ib, inf),
    };
  }

  // Points: the levels, then per fan its slices and limits.
  const lastLevel = levels[levels.length - 1];
  let nextPoint = lastLevel.base + lastLevel.he.nVerts;
  const fanWords = new U32(),
    sectorWords = new U32(),
    cosWords = new U32();
  const cosAt = new Map<number, number>();
  let maxDepth = 0;
  const sliceFans: number[] = [];
  fans.forEach((F, id) => {
    // Creases, corners, darts, boundaries: the radial blend's one exponent is a rougher model
    // there (two rates, along and across), so their last square is made 2^-3 smaller.
    if (F.D > 0 && !(F.rule === VRULE_SMOOTH && !F.boundary && F.sectors.every((q) => !q[0]))) F.D = Math.min(15, F.D + EXTRA_DEPTH_SHARP);
    const ns = F.sectors.length;
    const sliceBase = nextPoint;
    nextPoint += F.D + Math.ceil(F.D / 2) * 2 * ns;
    const limitBase = nextPoint;
    nextPoint += 3 + (F.rule === VRULE_SMOOTH ? 0 : 2 * F.n);
    maxDepth = Math.max(maxDepth, F.D);
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
    if (F.D > 15) throw new Error('fan depth > 15');
    fanWords.push(CC_FAN_WORD.pack({ sectors: ns, valence: F.n, boundary: F.boundary, rule: F.rule, depth: F.D }));
    fanWords.push(levels[F.level].base + F.x);
    fanWords.push(sliceBase);
    fanWords.push(sectorWords.n);
    fanWords.push(f32bits(F.alpha));
    fanWords.push(limitBase);
    fanWords.push(CC_PAIR_WORD.pack({ a: F.ia, b: F.ib }));
    fanWords.push(cosBase);
    for (const s of F.sectors) for (const w of s) sectorWords.push(w);
    if (F.D > 0) sliceFans.push(id);
  });
  // Pack the sliced fans into workgroups of 64 threads (a fan never straddles two).
  const threadWords = new U32();
  let used = WORKGROUP;
  for (const id of sliceFans) {
    const ns = fans[id].sectors.length;
    if (used + ns > WORKGROUP) {
      while (threadWords.n % WORKGROUP) threadWords.push(NONE);
      used = 0;
    }
    for (let i = 0; i < ns; i++) threadWords.push(CC_THREAD_WORD.pack({ fan: id, sector: i }));
    used += ns;
  }
  while (threadWords.n % WORKGROUP) threadWords.push(NONE);

  // Triangles → regions.
  const nT = prepared.triangleCount;
  const triRegion = new Uint32Array(3 * nT);
  const polyAt = new Map<number, number>();
  const poly: number[] = [];
  const triKind = new Uint8Array(nT);
  for (let t = 0; t < nT; t++) {
    const f = prepared.triFace[t];
    const start = cage.faceOffsets[f];
    const n = cage.faceOffsets[f + 1] - start;
    const k = prepared.triFan[t];
    const centred = fannedRoundCentre(n);
    const corner = (j: number) => cage.faceIndices[start + (j % n)];
    if ((centred ? prepared.triVerts[3 * t] < nV0 : prepared.triVerts[3 * t] !== corner(0)) || prepared.triVerts[3 * t + 1] !== corner(k))
      throw new Error(`triangle ${t} is not a fan triangle of face ${f}`);
    const dd = n === 4 ? faceDepth[f] : faceDepth[f] - 1;
    triRegion[3 * t] = faceRegion[f] >= 0 ? faceRegion[f] : NONE;
    triRegion[3 * t + 1] = CC_TRI_WORD.pack({ corners: n, fan: k, centred: centred ? 1 : 0, depth: Math.max(0, dd) });
    if (n !== 4) {
      let at = polyAt.get(n);
      if (at === undefined) {
        polyAt.set(n, (at = poly.length / 2));
        for (let j = 0; j < n; j++) poly.push(Math.cos((2 * Math.PI * j) / n), Math.sin((2 * Math.PI * j) / n));
      }
      triRegion[3 * t + 2] = at;
    }
    triKind[t] = faceKindOf[f];
  }

  const parts: Uint32Array[] = [
    triRegion,
    new Uint32Array(Float32Array.from(poly).buffer),
    regionWords.view,
    patchIdx.view,
    fanWords.view,
    sectorWords.view,
    threadWords.view,
    cosWords.view,
    rules.view,
    inputs.view,
    vertexFan,
  ];
  const offs: number[] = [];
  let total = 0;
  for (const p of parts) {
    offs.push(total);
    total += p.length;
  }
  const words = new Uint32Array(total);
  parts.forEach((p, i) => words.set(p, offs[i]));
  const pointCount = nextPoint - nV0;
  return {
    words,
    offTri: offs[0],
    offPoly: offs[1],
    offRegions: offs[2],
    offPatchIdx: offs[3],
    offFans: offs[4],
    offSectors: offs[5],
    offThreads: offs[6],
    offCos: offs[7],
    offRules: offs[8],
    offInputs: offs[9],
    offVertexFan: offs[10],
    pointCount,
    levelRanges,
    fanCount: fans.length,
    sliceWorkgroups: threadWords.n / WORKGROUP,
    maxDepth,
    regionCount: regionWords.n / 2,
    patchCount,
    singleCreaseCount,
    sectorRegionCount,
    levels: levels.length - 1,
    triKind,
    faceDepth,
    faceRegion,
    regions: regionWords.view.slice(),
    fans: fanWords.view.slice(),
    triRegion,
    cageVertexCount: nV0,
    gpuBytes: 4 * total + 12 * pointCount,
  };
}

/**
 * Where a point of the surface is taken from (the CPU side of the evaluator's region lookup,
 * wgsl/cc/surface.wgsl): for the checks, which split the exact region from the blended square
 * round extraordinary vertices. (x, y): the quad's (u, v) or sub-face k's (s, t).
 */
export function regionOf(cc: CatmullClarkData, t: number, k: number, x: number, y: number): { blended: boolean; sector: boolean } {
  const info = cc.triRegion[3 * t + 1];
  const dd = CC_TRI_WORD.get(info, 'depth');
  const side = 1 << dd;
  const i = Math.min(Math.floor(x * side), side - 1),
    j = Math.min(Math.floor(y * side), side - 1);
  const reg = cc.triRegion[3 * t] + k * side * side + j * side + i;
  const w0 = cc.regions[2 * reg];
  if (CC_REGION_WORD.get(w0, 'kind') !== REGION_SECTOR) return { blended: false, sector: false };
  const [a, b] = rot(CC_REGION_WORD.get(w0, 'rot'), x * side - i, y * side - j);
  const off = CC_REGION_WORD.get(w0, 'offset');
  const D = CC_FAN_WORD.get(cc.fans[8 * cc.regions[2 * reg + 1]], 'depth');
  // Blended inside the step-D square: max(a, b)·2^-offset < 2^-D.
  return { blended: Math.max(a, b) * 2 ** (D - off) < 1, sector: true };
}

/** rot_r of the unit square: rot_1(x, y) = (y, 1 − x), rot_r = rot_1^r. */
export function rot(r: number, x: number, y: number): [number, number] {
  switch (r & 3) {
    case 0:
      return [x, y];
    case 1:
      return [y, 1 - x];
    case 2:
      return [1 - x, 1 - y];
    default:
      return [1 - y, x];
  }
}
