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
 *    faceOffsets[f]+j, [V(c_j), E(c_j c_j+1), F, E(c_j-1 c_j)]. Sharpness decays by s − 1 a level
 *    (DeRose, Kass, Truong 1998; OpenSubdiv's uniform creasing).
 *    Each new point carries a RULE (2 words: kind and counts, first input) and its inputs
 *    (point indices): face point (N corners), edge point (ends + the two new face points;
 *    sharpness s: smooth, or after the inputs when not 0: crease, blend), vertex point (v, far
 *    ends of its edges, its new face points; parent rule, child rule, and when either is not
 *    smooth, after the inputs: the two crease edges and the transitional weight W in f32 as
 *    OpenSubdiv computes it).
 * 2. Fans. A vertex x of level s is a fan centre ("eligible") when every point of its 2-ring
 *    other than x obeys the regular valence-4 masks: its faces are quads, each neighbour (1,0)
 *    is a valence-4 vertex whose only sharp edges are the two halves of the axis, of one
 *    sharpness (or a valence-3 boundary vertex on a boundary axis), and each diagonal (1,1) is
 *    a smooth interior valence-4 vertex. Then one refinement step of the fan reads only the
 *    axes' sharpness and the centre's rule: every other point touched is a face point, an edge
 *    point of an edge made inside a face (sharpness 0), or the vertex point of (1,0) / (1,1)
 *    above; and after one step the new (1,0), (1,1) are again of that kind, the axes one unit
 *    less sharp. So the slice kernel is exact at every depth for boundaries, creases into the
 *    EV, darts and corners alike, infinitely sharp or SEMI-SHARP: under uniform creasing (the
 *    default) a semi-sharp axis decays inside the kernel (wgsl/cc/slices.wgsl sliceStep: its
 *    edge and vertex points by its sharpness σ − k, OpenSubdiv's blends below 1), the centre,
 *    whose edges and own sharpness may be semi-sharp, takes each step's rule from a table
 *    (src/gpu/cc/fans.ts stepRules: parent and child rule, crease pair and transitional W, as
 *    the levels make a vertex point), and such a fan steps at least ceil(σ) + 1 times, so its
 *    limit is taken by the rule that holds once every value has decayed. A cage vertex on a
 *    straight semi-sharp crease is no fan centre (the single-crease patches and the closed-form
 *    limit take it, below); under Chaikin's rule (the halves of an edge decay differently)
 *    semi-sharp values never reach a fan, and the uniform levels decay them.
 * 3. Regions. Face f is split to the smallest depth d at which each of its level-d descendants
 *    is a regular patch (isRegularVertex at its 4 corners: smooth, boundary, infinitely sharp
 *    phantoms), a SINGLE-CREASE patch, or has an eligible fan centre at a corner (an EV SECTOR
 *    region; its fan may start at a coarser level s ≤ d: offset d − s). d = 0 for regular
 *    quads (1 region), 1 for quads at an EV (4), 2 where triangles are involved (16 per quad,
 *    12 per triangle), as in the talk's table, and deeper only where semi-sharp creases are
 *    neither single creases nor a fan's axes. A single-crease patch (singleCrease; Nießner, Loop, Greiner 2012, OpenSubdiv's
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
 * Limits (honest): where a semi-sharp crease is neither a single crease nor the axis of an
 * eligible fan (a crease that bends or changes its sharpness at a valence-4 vertex next to a
 * centre, a semi-sharp crease beside a semi-sharp boundary-like feature, Chaikin's rule) its
 * sharpness still decays by UNIFORM levels of the whole cage, ceil(σ) of them (more than
 * MAX_LEVEL = 6 is refused with a message, as are vertices of valence > 4,094, the fan word's
 * field, and faces of more than 64 corners). OpenSubdiv's 86 regression cages: catmark_car
 * and _bishop (σ ≈ 5-6 creases through valence-5 vertices and ending at darts) took 6 levels
 * and 266 / 231 KB per face before the fans took semi-sharp axes, now 1-2 levels and 1.4 /
 * 1.9 KB; _rook, _helmet, _hole_test2, _gregory_test7 (σ 7-9) were refused; the project's
 * creased box 3 levels and 6.8 KB, now 1 and 2.1 KB. Only the Chaikin cages keep deep levels
 * (catmark_chaikin1: 5 levels, 105 KB per face).
 *
 * GPU point space (f32 xyz in cageBuf; index p < ccCageVerts, the cage's vertex count: the cage
 * positions; p ≥ ccCageVerts at offPoints + 3(p − ccCageVerts)):
 *   [cage | level 1 | … | level G | fan slices | fan limits]
 *   slices of fan F (depth D, ns threads = sectors + 1 on a boundary), all as OFFSETS from the
 *     fan's anchor (its centre at level s: f32 precision of deep levels):
 *       centres   D points, the centre after step k = 1..D at slot k − 1;
 *       points    per stored step k, per sector j < ns, its 12 points (a, b), a ∈ 1..3, b ∈ 0..3
 *                 of its frame at 4(a − 1) + b: at D + 12(slot(k)·ns + j) (a boundary's
 *                 pseudo-sector has its axis points 0, 4, 8 only). Every step is stored,
 *                 slot(k) = k − 1; or, for a fan whose word has `odd` (CatmullClarkOptions.slices),
 *                 the odd steps only, slot(k) = (k − 1)/2: an even step is one step of the odd
 *                 one before, made again where it is read (wgsl/cc/slices.wgsl ccSliceMake, the
 *                 slice kernel's own step): half the slices' bytes, at four sectors' steps made
 *                 again per vertex on an even step (step L holds 3·4^-L of a sector region's
 *                 area: a fifth of it on even steps). The
 *                 build takes every step unless that exceeds SLICE_BUDGET_BYTES_PER_FACE (imrod,
 *                 all triangles: 6.6 → 4.0 KB per face). A fan wider than a workgroup keeps every
 *                 step (its kernel reads the step before from memory).
 *     Why all of them (patch-major): a point of the surface near the EV lies on sub-patch A, B
 *     or C of one sector at one step L, and those 16 points are this sector's 12 and a few of
 *     its neighbours' (wgsl/cc/surface.wgsl ccEvalRegion). The slice kernel computes them anyway
 *     (in workgroup memory, once per rebuild); storing them costs 12 points per sector and step
 *     (GPU subdivision data in all: imrod 6.6 KB per face with every step, 4.0 with the odd steps; suzanne 2.1, monsterfrog 1.4, bigguy 1.0) where keeping only the centre
 *     and the ring made every vertex redo up to L local steps of three sectors from the start
 *     level, the largest part of the exact surface's evaluation.
 *   Then the limits: P (absolute), T1, T2 (the vertex's: the factor rule, the flat baseline);
 *     then, at a crease or corner centre (rule not smooth), T1, T2 of each face i < n at
 *     3 + 2i, 4 + 2i: an infinitely sharp crease splits the tangent plane into sectors (one per
 *     span of faces between two sharp edges, one per face at a corner), and a face's corner
 *     takes the normal of its own (src/gpu/tess/prepare.ts splitCreases outputs a vertex once per
 *     sector). As the CPU reference (src/subdiv/limit.ts vertexLimit for that face).
 *
 * Static words (u32, appended to the tessellator's static buffer; offsets below are relative), the
 * sections of CC_STATIC (src/gpu/contract/cc.ts), in this order:
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
 *   fans     CC_FAN_WORDS (9) per fan: CC_FAN_WORD; anchor;
 *            slice base; sector base; alpha (f32); limit base; CC_PAIR_WORD (ia, ib); cos
 *            base; step rules (word offset in `sectors`, or CC_NONE)
 *   sectors  7 per sector (ns per fan): the axis word (0 smooth, CC_AXIS_INFINITE, or a
 *            semi-sharp axis's σ at level s as f32 bits), (1,0) (2,0) (1,1) (2,1) (1,2) (2,2)
 *            at level s; the boundary pseudo-sector (axis n) has only (1,0), (2,0); then, for
 *            a fan with a semi-sharp axis, 3 words per step k = 1..D: the centre's
 *            CC_STEP_RULE_WORD, crease pair and W (f32) (src/gpu/cc/fans.ts stepRules)
 *   threads  64 per slice workgroup: fan | sector << 24, or ~0 (idle)
 *   cos      per valence n used by a smooth fan: cos(2πi/n), i < n, then 1/(4λ−1)
 *   rules    2 per point of levels ≥ 1: w0, first input. w0 = kind (0 face, 1 edge, 2 vertex) |
 *            face: n << 8; edge: sharp << 2 | n << 8 (n = 2 on a boundary, else 4);
 *            vertex: parent rule << 2 | child rule << 4 | edges << 8 | faces << 20
 *   inputs   point indices read by the rules, each rule's followed by its parameters (edge:
 *            sharpness f32 if flagged; vertex with a non-smooth rule: ia | ib << 16, W f32)
 *   vertexFan per prepared vertex (the cage's, then the face centres of prepare.ts),
 *            CC_VERTEX_LIMIT_WORD: its fan (limit position and normal for the factor rule), or
 *            (crease bit) the word offset of its crease record in patchIdx, or ~0
 *
 * The files: this one holds the data's shape and buildCatmullClark, the driver of the steps;
 * src/gpu/cc/levels.ts (1: levels and point rules), src/gpu/cc/fans.ts (2: fans, vertex limits,
 * their packing), src/gpu/cc/regions.ts and src/gpu/cc/single-crease.ts (3: regions, tri words).
 */
import { LimitError } from '../../mesh/errors.ts';
import {
  type Cage,
  type SubdivOptions,
  type Topology,
  DEFAULT_OPTIONS,
  buildTopology,
  classify,
  computeSharpness,
} from '../../mesh/index.ts';
import type { PreparedMesh } from '../tess/prepare.ts';
import { WORKGROUP_SIZE } from '../contract/constants.ts';
import { CC_STATIC, type CcSection } from '../contract/cc.ts';
import type { ArenaLayout } from '../contract/define.ts';
import { CC_FAN_WORD, CC_FAN_WORDS, CC_MAX_FAN_SECTORS, CC_REGION_WORD, CC_TRI_WORD } from './words.ts';
import { type LevelStack, levelStack } from './levels.ts';
import { type FanTable, type SliceSteps, fanTable, packFans, packThreads, vertexLimits } from './fans.ts';
import { REGION_SECTOR, type Regions, type TriangleRegions, buildRegions, triangleRegions } from './regions.ts';

export interface CatmullClarkOptions {
  /** Subdivision options (default: the cage file's, over OpenSubdiv's defaults). */
  subdiv?: SubdivOptions;
  /**
   * Which steps' sector points the fans' slices keep (src/gpu/cc/fans.ts SliceSteps). 'auto'
   * (default): every step's (the faster evaluator), unless that puts the subdivision data above
   * SLICE_BUDGET_BYTES_PER_FACE, then the odd steps' (half the slices' bytes).
   */
  slices?: SliceSteps | 'auto';
}

/**
 * The memory bound of the subdivision data that 'auto' keeps to where halving the slices can: 4 KB
 * per cage face (the talk's models: every step's slices cost imrod, all triangles with ~1.5 fans of
 * depth 6 per face, 6.6 KB; its odd steps' 4.0 KB; the others stay at 1-2.1 KB with every step).
 */
export const SLICE_BUDGET_BYTES_PER_FACE = 4096;

export interface CatmullClarkData {
  words: Uint32Array;
  /** Where each section lies in `words` (CC_STATIC). */
  layout: ArenaLayout<CcSection>;
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
  /** Some face is not a quad (the evaluator's n-gon parametrisation is needed). */
  hasNgons: boolean;
  /** Some region takes phantom points (a boundary, an infinitely sharp edge or axis). */
  hasPhantoms: boolean;
  /** Some fan has a semi-sharp axis (it decays in the slices; its sub-patches next to the axis
   * take the crease basis): the evaluator carries the crease basis. */
  semiAxes: boolean;
  /** Some fan keeps its odd steps' sector points only (CatmullClarkOptions.slices): the evaluator makes the even steps'. */
  oddSlices: boolean;
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

/**
 * A vertex's valence never changes under refinement, so one whose fan has more sectors than its
 * word holds can never be a fan centre: say so now rather than "too many levels" later. Faces
 * wider than a workgroup too (their centre's fan would be wide; the n-gon evaluator's tables are
 * sized for a workgroup).
 */
function refuseWideVertices(topo: Topology): void {
  // A face's centre is a vertex of valence n after one step: an n-gon wider than a workgroup has
  // a centre no fan can take, and its regions would refine to MAX_LEVEL and fail there, slowly.
  for (let f = 0; f < topo.nFaces; f++) {
    const n = topo.faceOffsets[f + 1] - topo.faceOffsets[f];
    if (n > WORKGROUP_SIZE)
      throw new LimitError(
        `face ${f + 1} has ${n} corners; the Catmull-Clark surface's GPU build takes faces of at most ${WORKGROUP_SIZE} (its centre becomes a vertex of valence ${n})`,
      );
  }
  for (let v = 0; v < topo.nVerts; v++) {
    const faces = topo.vertHeOffsets[v + 1] - topo.vertHeOffsets[v];
    if (faces + (topo.vertBoundary[v] ? 1 : 0) > CC_MAX_FAN_SECTORS)
      throw new LimitError(
        `vertex ${v + 1} has ${faces} faces round it; the Catmull-Clark surface's GPU build takes at most ${CC_MAX_FAN_SECTORS - (topo.vertBoundary[v] ? 1 : 0)} (its fan word's sector field)`,
      );
  }
}

/**
 * Build the topology-only Catmull-Clark data of a cage (its prepared triangulation gives the triangle order).
 * The steps run in this order because each makes what the next reads, and the regions and vertex
 * limits make levels and fans on demand, in the order they ask: regions, then vertex limits, then
 * the packing of the fans (whose depths are final only then), the slice threads, the triangles.
 */
export function buildCatmullClark(cage: Cage, prepared: PreparedMesh, opts: CatmullClarkOptions = {}): CatmullClarkData {
  const options: SubdivOptions = opts.subdiv ?? { ...DEFAULT_OPTIONS, ...cage.fileOptions };
  const topo = buildTopology(cage);
  const sharp = computeSharpness(cage, topo, options);
  const cls = classify(topo, sharp);
  refuseWideVertices(topo);
  const nV0 = topo.nVerts;
  const lv = levelStack(topo, sharp, options.creasing === 'chaikin');
  const ft = fanTable(lv.level);
  const regions = buildRegions(topo, sharp, cls, lv, ft);
  const vertexFan = vertexLimits(prepared, topo, lv, ft, regions.patchIdx);
  const tris = triangleRegions(cage, prepared, nV0, regions);
  const pack = (slices: SliceSteps) => packData(nV0, lv, ft, regions, vertexFan, tris, slices);
  const mode = opts.slices ?? 'auto';
  let data = pack(mode === 'auto' ? 'every' : mode);
  if (mode === 'auto' && data.gpuBytes > SLICE_BUDGET_BYTES_PER_FACE * topo.nFaces && data.fanCount > 0) data = pack('odd');
  // The static words, once, for the layout chosen.
  const { sections, ...rest } = data;
  const words = new Uint32Array(rest.layout.words);
  for (const k of CC_STATIC.names) words.set(sections[k], rest.layout.offset[k]);
  return { words, ...rest };
}

/** The sections and the point space of the build, its fans' slices keeping `slices` steps (all
 * but the static words' copy: packing is cheap, the copy is not where the levels are large). */
function packData(
  nV0: number,
  lv: LevelStack,
  ft: FanTable,
  regions: Regions,
  vertexFan: Uint32Array,
  { triRegion, poly, triKind }: TriangleRegions,
  slices: SliceSteps,
): Omit<CatmullClarkData, 'words'> & { sections: Record<CcSection, Uint32Array> } {
  const { fanWords, sectorWords, cosWords, maxDepth, sliceFans, nextPoint, axisPhantoms, semiAxes } = packFans(ft.fans, lv.levels, slices);
  const threadWords = packThreads(ft.fans, sliceFans);
  const { levels, rules, inputs, levelRanges } = lv;
  const { fans } = ft;
  const { regionWords, patchIdx, faceRegion, faceDepth, patchCount, singleCreaseCount, sectorRegionCount } = regions;

  const sections: Record<CcSection, Uint32Array> = {
    tri: triRegion,
    poly: new Uint32Array(Float32Array.from(poly).buffer),
    regions: regionWords.view,
    patchIdx: patchIdx.view,
    fans: fanWords.view,
    sectors: sectorWords.view,
    threads: threadWords.view,
    cos: cosWords.view,
    rules: rules.view,
    inputs: inputs.view,
    vertexFan,
  };
  const layout = CC_STATIC.layout(Object.fromEntries(CC_STATIC.names.map((k) => [k, sections[k].length])) as Record<CcSection, number>);
  const pointCount = nextPoint - nV0;
  return {
    sections,
    layout,
    pointCount,
    levelRanges,
    fanCount: fans.length,
    sliceWorkgroups: threadWords.n / WORKGROUP_SIZE,
    maxDepth,
    regionCount: regionWords.n / 2,
    patchCount,
    singleCreaseCount,
    sectorRegionCount,
    levels: levels.length - 1,
    triKind,
    hasNgons: poly.length > 0,
    hasPhantoms: axisPhantoms || regionMasks(regionWords.view),
    semiAxes,
    oddSlices: slices === 'odd' && sliceFans.some((id) => fans[id].sectors.length <= WORKGROUP_SIZE),
    faceDepth,
    faceRegion,
    regions: regionWords.view.slice(),
    fans: fanWords.view.slice(),
    triRegion,
    cageVertexCount: nV0,
    gpuBytes: 4 * layout.words + 12 * pointCount,
  };
}

/** Whether some region word has a phantom mask (a patch at a boundary or infinitely sharp edge). */
function regionMasks(regions: Uint32Array): boolean {
  for (let r = 0; r < regions.length; r += 2) if (CC_REGION_WORD.get(regions[r], 'mask') !== 0) return true;
  return false;
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
  const D = CC_FAN_WORD.get(cc.fans[CC_FAN_WORDS * cc.regions[2 * reg + 1]], 'depth');
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
