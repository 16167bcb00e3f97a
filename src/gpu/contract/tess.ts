/**
 * The compute tessellator's side of the contract (src/gpu/tess/tessellator.ts, wgsl/tess/*.wgsl):
 * its three buffers as arenas (TESS_STATIC, TESS_CAGE, TESS_WORK), whose offsets are fields of its
 * uniforms (TESS_PARAMS); its one bind group (TESS_GROUP), of which each pass binds what its entry
 * point uses; the scan's uniforms and group (SCAN_PARAMS, SCAN_GROUP); the packed words its
 * shaders read (the pattern frame, the bary word, the owner word, the ACC and displacement
 * triangle words), the table header, and its constants. What its shaders start with is assembled
 * in contract.ts (tessPrelude, scanPrelude).
 */
import { ONE } from '../../pattern/fixed.ts';
import { TABLE_HEADER_FIELDS } from '../../pattern/tables.ts';
import { STRIP_DP_VERTICES } from '../../pattern/clamped.ts';
import { CC_STATIC } from './cc.ts';
import { SCAN_ITEMS, SCAN_WORKGROUP_SIZE } from './constants.ts';
import { defineArena, defineBindGroup, defineBits } from './define.ts';
import { defineStruct } from './layout.ts';

/**
 * The pattern frame of a triangle (src/pattern/clamped.ts chooseFrame; packed per triangle by
 * prepare.ts packPatternFrame and read by wgsl/tess/pattern.wgsl): the corners playing A, B, C, the
 * edges playing bottom, left, right, whether each of those runs against its edge's line, and
 * whether the frame is mirrored.
 */
export const PATTERN_FRAME_WORD = defineBits('PatternFrameWord', {
  a: [0, 2],
  b: [2, 2],
  c: [4, 2],
  bottomEdge: [6, 2],
  leftEdge: [8, 2],
  rightEdge: [10, 2],
  flipBottom: [12, 1],
  flipLeft: [13, 1],
  flipRight: [14, 1],
  mirrored: [15, 1],
});

/**
 * An output vertex's barycentric weights on its source triangle (TessellatedMesh.bary, types.ts):
 * w1 and w2 in units of 2^-16. A vertex at corner 1 or 2 is stored as a sentinel instead
 * (BARY_CORNER1, BARY_CORNER2): their fields would sum past 2^16, which no real point does
 * (w1 + w2 ≤ 2^16, and a weight of exactly 2^16 is a corner).
 */
export const BARY_WORD = defineBits('BaryWord', { w1: [0, 16], w2: [16, 16] });
export const BARY_CORNER1 = 0xffffffff;
export const BARY_CORNER2 = 0xfffffffe;

/** The three weights (w0, w1, w2) of a bary word, in units of 2^-16 (they sum to 2^16). */
export function decodeBary(word: number): [number, number, number] {
  if (word === BARY_CORNER1) return [0, 65536, 0];
  if (word === BARY_CORNER2) return [0, 0, 65536];
  const { w1, w2 } = BARY_WORD.unpack(word);
  return [65536 - w1 - w2, w1, w2];
}

// ---------------------------------------------------------------------------------------------
// The compute tessellator (tessellator.ts, wgsl/tess/*.wgsl)

/**
 * The budget's candidate scales of every factor, largest first (src/gpu/tess/factors.ts
 * budgetCandidate is the CPU's twin of the choice): a rebuild counts its output at all of them in
 * one pass (wgsl/tess/factors.wgsl, count.wgsl), sums them in one multi-lane scan and takes the
 * first that fits the output buffers (wgsl/tess/scan.wgsl budget), so no factor or count is ever
 * computed twice and the chain of dispatches is the same length whatever the camera. Counts grow
 * about as factor², so each step of 2^-1/2 about halves them; the last candidate (0) is factor 1
 * everywhere, which setMesh checks always fits.
 */
export const BUDGET_SCALES = [1, 2 ** -0.5, 2 ** -1, 2 ** -1.5, 2 ** -2, 2 ** -2.5, 2 ** -3, 0] as const;
/** How many candidate scales each rebuild counts at (the lanes of the per-edge and per-triangle
 * counts in TESS_WORK). */
export const BUDGET_CANDIDATES = BUDGET_SCALES.length;
export const SCAN_BLOCK = SCAN_WORKGROUP_SIZE * SCAN_ITEMS;
/** Prefix sums per candidate: edge interior points, triangle interior vertices, triangles, rows
 * (TESS_SCANS). */
export const SCANS = 4;
/** 1.0 in the 16.16 fixed point of factors and barycentric weights (src/pattern/fixed.ts). */
export { ONE };
/** A cage vertex that no triangle uses (its OwnerWord). */
export const NO_OWNER = 0xffffffff;
/** The budget state words (work's `budget` array), by index: whether the budget was chosen, the
 * candidate it took, that candidate's scale (f32 bits), and whether it fits. */
export const BUDGET = { ACCEPTED: 0, CANDIDATE: 1, SCALE: 2, FITS: 3 } as const;

/** The tessellator shaders' numbers beyond the shared ones (all u32), by their WGSL names. */
export const TESS_CONSTANTS = {
  BUDGET_CANDIDATES,
  SCANS,
  ONE,
  NO_OWNER,
  BARY_CORNER1,
  BARY_CORNER2,
  STRIP_DP_VERTICES,
  ...Object.fromEntries(Object.entries(BUDGET).map(([k, v]) => [`BUDGET_${k}`, v])),
  BUDGET_WORDS: Object.keys(BUDGET).length,
} as Readonly<Record<string, number>>;

/**
 * Which triangle of the mesh owns a welded vertex (prepare.ts vertexOwner, edgeOwner; read by
 * wgsl/tess/weld.wgsl): the triangle, and its corner (a vertex) or its local edge i, which runs
 * from corner i to corner i + 1 (an edge). NO_OWNER marks a vertex no triangle uses.
 */
export const OWNER_WORD = defineBits('OwnerWord', { corner: [0, 2], tri: [2, 30] });

/** WGSL getters of the pattern tables' header words (src/pattern/tables.ts TABLE_HEADER_FIELDS,
 * which its writer and reader index by): `fn tableHeader_stateCount() -> u32` and so on, reading
 * `buffer[params.offTables + i]`. */
export function tableHeaderWgsl(buffer: string, params: string): string {
  return TABLE_HEADER_FIELDS.map((f, i) => `fn tableHeader_${f}() -> u32 { return ${buffer}[${params}.offTables + ${i}u]; }`)
    .join('\n')
    .concat('\n');
}

/** What the tessellator's arenas are sized from. */
export interface TessSizes {
  vertices: number;
  /** Output vertices past the vertices: the extra sectors of crease and corner vertices
   * (prepare.ts slotOwner) where the surface splits normals at creases, else 0. */
  extraSlots: number;
  edges: number;
  triangles: number;
  /** The pattern tables' largest factor (a triangle has at most maxFactor + 1 rows). */
  maxFactor: number;
  /** Words of the pattern tables. */
  tableWords: number;
  /** Words of the Catmull-Clark tables (src/gpu/cc/build.ts), 0 without them. */
  ccWords: number;
  /** Refined Catmull-Clark points (3 floats each), 0 without them. */
  ccPoints: number;
  /** Cage vertices whose limit position and normal the patch build writes: all of them with the
   * Catmull-Clark surface, else 0. */
  limitVertices: number;
  /** Triangles with an ACC patch word (ACC_TRI_WORD): all of them with an ACC surface, else 0. */
  accTriangles: number;
  /** Words of the ACC patch table (2 per patch) and ACC control points, 0 without an ACC surface. */
  accPatchWords: number;
  accPoints: number;
  /** Displacement (src/gpu/tess/displacement-map.ts), all 0 without it: words of the packed height map,
   * triangles with three DISP_TRI words (all of them), edges with three factor words (all of
   * them), and face corners with a uv (2 floats each). */
  heightWords: number;
  dispTriangles: number;
  dispEdges: number;
  cornerUvs: number;
}

/**
 * staticBuf (u32, read-only, written once per mesh): the pattern tables, the mesh topology of
 * prepare.ts (named as its PreparedMesh arrays), then the Catmull-Clark tables (their own offsets
 * within, cc/build.ts, reach the shaders as the cc* fields of Params).
 */
export const TESS_STATIC = defineArena<
  | 'tables'
  | 'triVerts'
  | 'triEdges'
  | 'triPatternFrame'
  | 'edgeVerts'
  | 'edgeOwner'
  | 'edgeTwin'
  | 'vertexOwner'
  | 'cornerSlot'
  | 'slotOwner'
  | 'edgeSplit'
  | 'cc'
  | 'accTri'
  | 'accPatches'
  | 'heightTexels'
  | 'dispTri'
  | 'dispEdge',
  TessSizes
>([
  ['tables', (s) => s.tableWords],
  ['triVerts', (s) => 3 * s.triangles],
  ['triEdges', (s) => 3 * s.triangles],
  ['triPatternFrame', (s) => s.triangles],
  ['edgeVerts', (s) => 2 * s.edges],
  ['edgeOwner', (s) => s.edges],
  ['edgeTwin', (s) => s.edges],
  ['vertexOwner', (s) => s.vertices],
  // Split normals at infinitely sharp creases (prepare.ts splitCreases; the Catmull-Clark surface
  // only, elsewhere cornerSlot is triVerts and edgeSplit 0): the output vertex of each triangle
  // corner, the owner corner of each extra output vertex, and per edge 1 where its points are
  // output once per side.
  ['cornerSlot', (s) => 3 * s.triangles],
  ['slotOwner', (s) => s.extraSlots],
  ['edgeSplit', (s) => s.edges],
  ['cc', (s) => s.ccWords],
  ['accTri', (s) => s.accTriangles],
  ['accPatches', (s) => s.accPatchWords],
  // Displacement (src/gpu/tess/displacement-map.ts has the layout): the height map's texels packed 4
  // (8-bit) or 2 (16-bit) to a word, row-major from the image's top row; per triangle three
  // words (its face's first corner in cornerUvs, DISP_TRI_WORD, the face); per edge three f32 words for
  // the factor rule (the lowest and highest height SAMPLE over its faces, its length in texels).
  ['heightTexels', (s) => s.heightWords],
  ['dispTri', (s) => 3 * s.dispTriangles],
  ['dispEdge', (s) => 3 * s.dispEdges],
]);

/**
 * Word 3t + 1 of dispTri (word 3t is the first corner of the triangle's face in cornerUvs, word
 * 3t + 2 the face): the face's corner count and which triangle of it t is (prepare.ts triFan:
 * corners (0, fan, fan + 1), or (centre, fan, fan + 1 mod n) when centred), from which
 * wgsl/tess/displace.wgsl maps the triangle's weights to the face parameter that the uvs are
 * interpolated over (src/mesh/uv.ts: bilinear on quads, the kite sub-faces on other faces).
 */
export const DISP_TRI_WORD = defineBits('DispTriWord', { corners: [0, 15], centred: [15, 1], fan: [16, 16] });

/**
 * Per triangle with an ACC surface (wgsl/acc/surface-tess.wgsl): its ACC patch (= cage face) and
 * the patch parameter (u, v) of its three corners, each 0 or 1 (bit 2i: u_i, bit 2i + 1: v_i), so
 * that (u, v) = Σ w_i (u_i, v_i) for the triangle's weights w (src/gpu/acc/error.ts
 * accTriangleMap builds it: quads split on their 0–2 diagonal, triangles (u, v) = (w1, w2)).
 */
export const ACC_TRI_WORD = defineBits('AccTriWord', { corners: [0, 6], face: [6, 26] });

/**
 * ACC_TRI_WORD's `corners` field, bit by bit: the patch parameter (u_i, v_i) of corner i, each 0
 * or 1. Read by wgsl/acc/surface-tess.wgsl, wgsl/acc/heat.wgsl and src/gpu/acc/error.ts.
 */
export const ACC_TRI_CORNERS = defineBits('AccTriCorners', { u0: [0, 1], v0: [1, 1], u1: [2, 1], v1: [3, 1], u2: [4, 1], v2: [5, 1] });

/**
 * cageBuf (f32, rewritten when the cage moves): positions and vertex normals, 3 floats each; the
 * Phong surface's α of each triangle's three edges (prepare.ts triPhongAlpha, which follows the
 * normals); with the Catmull-Clark surface, its refined points (point p ≥ ccCageVerts at
 * offCtrl + 3(p − ccCageVerts)) and the limit positions and normals of the cage vertices
 * (wgsl/cc/build.wgsl writes them).
 */
export const TESS_CAGE = defineArena<
  'positions' | 'normals' | 'phongAlpha' | 'ctrl' | 'limitPositions' | 'limitNormals' | 'accPoints' | 'cornerUvs',
  TessSizes
>([
  ['positions', (s) => 3 * s.vertices],
  ['normals', (s) => 3 * s.vertices],
  ['phongAlpha', (s) => 3 * s.triangles],
  ['ctrl', (s) => 3 * s.ccPoints],
  ['limitPositions', (s) => 3 * s.limitVertices],
  ['limitNormals', (s) => 3 * s.limitVertices],
  // ACC control points (4 floats each: xyz, w unused), copied from the ACC patch build's buffer
  // every frame, so the emit passes read no more storage buffers than with the other surfaces.
  ['accPoints', (s) => 4 * s.accPoints],
  // Displacement: the uv of every face corner (2 floats, at 2h for corner h = faceOffsets[f] + j:
  // src/mesh/uv.ts faceCornerUvs), so a seam is just two corners with different uvs.
  ['cornerUvs', (s) => 2 * s.cornerUvs],
]);

/**
 * work (u32 scratch, rewritten every rebuild): the factor each triangle's bulge asks for (an f32's
 * bits, wgsl/tess/factor-bulge.wgsl); per edge the segments its surface normal's turn asks for (f32
 * bits, the same pass: the one array kept between rebuilds, rewritten when the surface changes,
 * Params.turnRefresh); per edge its factor before the budget (edgeFactor, f32
 * bits), and at the chosen candidate its 16.16 factor, line state and segments (the scan's last
 * pass writes them, wgsl/tess/common.wgsl edgeAtCandidate: what the weld, plan and emit read);
 * per edge its interior points and per triangle its interior vertices, triangles and rows at
 * every budget candidate (BUDGET_SCALES): lane c of an array over n elements is its words
 * c·n … c·n + n − 1; the exclusive prefix sums of the chosen candidate (n + 1 words: the total
 * at n); the planned rows
 * (two words per row, at most maxFactor + 1 rows a triangle), each triangle's gap-strip moves
 * (gapMoveWords words a triangle), the scan's block sums (one run of scanSumsWords per lane:
 * SCANS lanes per candidate), the budget state (BUDGET).
 */
export const TESS_WORK = defineArena<
  | 'edgeFactor'
  | 'edgeF'
  | 'edgeState'
  | 'edgeSegs'
  | 'edgeInterior'
  | 'edgeBase'
  | 'triBulge'
  | 'edgeTurn'
  | 'triVertCount'
  | 'triVertBase'
  | 'triTriCount'
  | 'triTriBase'
  | 'triRowCount'
  | 'triRowBase'
  | 'rows'
  | 'gapMoves'
  | 'sums'
  | 'budget',
  TessSizes
>([
  ['edgeFactor', (s) => s.edges],
  ['edgeF', (s) => s.edges],
  ['edgeState', (s) => s.edges],
  ['edgeSegs', (s) => s.edges],
  ['edgeInterior', (s) => BUDGET_CANDIDATES * s.edges],
  ['edgeBase', (s) => s.edges + 1],
  ['triBulge', (s) => s.triangles],
  ['edgeTurn', (s) => s.edges],
  ['triVertCount', (s) => BUDGET_CANDIDATES * s.triangles],
  ['triVertBase', (s) => s.triangles + 1],
  ['triTriCount', (s) => BUDGET_CANDIDATES * s.triangles],
  ['triTriBase', (s) => s.triangles + 1],
  ['triRowCount', (s) => BUDGET_CANDIDATES * s.triangles],
  ['triRowBase', (s) => s.triangles + 1],
  ['rows', (s) => 2 * (s.maxFactor + 1) * s.triangles],
  ['gapMoves', (s) => gapMoveWords(s.maxFactor) * s.triangles],
  ['sums', (s) => SCANS * BUDGET_CANDIDATES * scanSumsWords(Math.max(s.edges, s.triangles))],
  ['budget', () => Object.keys(BUDGET).length],
]);

/**
 * Words of one triangle's gap strip (wgsl/tess/plan.wgsl writes them, the emit reads them): a
 * large strip's moves, one bit a move, as src/pattern/clamped.ts gapMergeSteps (at most
 * (nb − 1) + nl + nr − 1 moves, and a line has at most maxFactor + 1 segments, 3 on [1, 2], so
 * 3·(maxFactor + 1) bits are enough), or a small strip's triangles (clamped.ts
 * stripTriangulation, at most STRIP_DP_VERTICES − 2 of them, 16 bits each).
 * wgsl/tess/pattern.wgsl gapMoveWords computes the same.
 */
export function gapMoveWords(maxFactor: number): number {
  return Math.max(Math.ceil((3 * (maxFactor + 1)) / 32), Math.ceil((STRIP_DP_VERTICES - 2) / 2));
}

/** Block-sum words one scan of up to n values needs (its blocks, and one spare). */
export function scanSumsWords(n: number): number {
  return Math.ceil(Math.max(n, 1) / SCAN_BLOCK) + 1;
}

/** The prefix sums of each budget candidate, in lane order (lane SCANS·c + i of candidate c): what
 * is summed into what (TESS_WORK arrays), over edges or triangles. scanLanesWgsl gives the scan
 * shader the same table. */
export const TESS_SCANS = [
  { from: 'edgeInterior', to: 'edgeBase', over: 'edges' },
  { from: 'triVertCount', to: 'triVertBase', over: 'triangles' },
  { from: 'triTriCount', to: 'triTriBase', over: 'triangles' },
  { from: 'triRowCount', to: 'triRowBase', over: 'triangles' },
] as const satisfies readonly { from: string; to: string; over: 'edges' | 'triangles' }[];

/**
 * The tessellator's uniforms (`params` in every tessellator shader). The arenas' offsets are
 * spread in from TESS_STATIC, TESS_CAGE and TESS_WORK; the Catmull-Clark fields are named by
 * src/gpu/cc/build.ts and read by wgsl/cc/build.wgsl and wgsl/cc/surface.wgsl.
 */
export const TESS_PARAMS = defineStruct('Params', [
  ['viewProj', 'mat4x4<f32>', 'World to clip space of the camera (frustum culling of edges).'],
  ['eye', 'vec4<f32>', "xyz: the camera's position."],
  ['nVerts', 'u32'],
  ['nSlots', 'u32', 'Output vertices of the corners: nVerts, then the extra sectors (slotOwner); the edge points follow.'],
  ['nTris', 'u32'],
  ['nEdges', 'u32'],
  ['maxFactor', 'u32'],
  ['vertexCapacity', 'u32'],
  ['triangleCapacity', 'u32'],
  ['mode', 'u32', '0: fixedFactor everywhere; 1: adaptive (screen-space error).'],
  ['fixedFactor', 'f32'],
  ['lodScale', 'f32'],
  ['pixelAngle', 'f32'],
  ...TESS_STATIC.offsetFields,
  ...TESS_CAGE.offsetFields,
  ...TESS_WORK.offsetFields,
  // What the factor rule reads (cageBuf offsets): the cage, or the limit surface at its vertices.
  ['offFactorPos', 'u32'],
  ['offFactorNormal', 'u32'],
  // Catmull-Clark (src/gpu/cc/build.ts): staticBuf word offsets of its tables (CC_STATIC: ccTri,
  // ccPoly, …) and their sizes.
  ['ccCageVerts', 'u32', 'Points p below it are the cage vertices (cageBuf 3p), the rest refined points (offCtrl).'],
  ...CC_STATIC.offsetFields,
  ['nFans', 'u32'],
  ['ccSliceGroups', 'u32'],
  ['ccMaxDepth', 'u32'],
  ['turnRefresh', 'u32', "1: the bulge pass recomputes each edge's turn term (work edgeTurn): the surface changed since."],
  // Displacement (src/gpu/tess/displacement-map.ts, wgsl/tess/displace.wgsl): h = (sample − dispMid)·dispScale
  // along the surface normal; the map is dispWidth × dispHeight texels of dispBits bits.
  ['dispOn', 'u32', '1: displace every output vertex (and count the heights in the factor rule).'],
  ['dispBits', 'u32', '8 or 16.'],
  ['dispWidth', 'u32'],
  ['dispHeight', 'u32'],
  ['dispWrap', 'u32', '0: repeat, 1: clamp to edge (src/mesh/heightmap.ts).'],
  ['dispScale', 'f32'],
  ['dispMid', 'f32'],
] as const);

/** Words of the tessellator's fixed-size outputs: drawIndexedIndirect's arguments, the counts
 * (src/gpu/contract/tessellated-mesh.ts: vertices, triangles, the accepted scale as f32 bits, the
 * budget candidate), and the indirect dispatch of the vertices' emit that the budget sizes (one
 * thread per output vertex; the triangles' emit is a workgroup per cage triangle). */
export const TESS_FIXED_WORDS = { drawArgs: 5, counts: 4, emitArgs: 3 } as const;

/** One binding group for every tessellator pass; each pass's layout holds the bindings its entry
 * point uses (usedBindings), so the numbers below are the only place they are written. */
export const TESS_GROUP = defineBindGroup(0, {
  params: { binding: 0, space: 'uniform', type: 'Params' },
  staticBuf: { binding: 1, space: 'read', type: 'array<u32>', doc: 'TESS_STATIC: pattern tables, topology, Catmull-Clark tables.' },
  cageBuf: { binding: 2, space: 'read', type: 'array<f32>', doc: 'TESS_CAGE: positions, normals (Catmull-Clark: refined points, limits).' },
  work: { binding: 3, space: 'read_write', type: 'array<u32>', doc: 'TESS_WORK: counts, prefix sums, rows, budget state.' },
  outPositions: {
    binding: 4,
    space: 'read_write',
    type: 'array<f32>',
    doc: 'The output mesh (src/gpu/contract/tessellated-mesh.ts TessellatedMesh).',
  },
  outNormals: { binding: 5, space: 'read_write', type: 'array<f32>' },
  outBary: { binding: 6, space: 'read_write', type: 'array<u32>' },
  outSrcTri: { binding: 7, space: 'read_write', type: 'array<u32>' },
  outIndices: { binding: 8, space: 'read_write', type: 'array<u32>' },
  drawArgs: {
    binding: 9,
    space: 'read_write',
    type: `array<u32, ${TESS_FIXED_WORDS.drawArgs}>`,
    doc: "Written with the budget's choice (wgsl/tess/scan.wgsl scanDown), as counts and emitArgs (TESS_FIXED_WORDS).",
  },
  counts: { binding: 10, space: 'read_write', type: `array<u32, ${TESS_FIXED_WORDS.counts}>` },
  emitArgs: { binding: 11, space: 'read_write', type: `array<u32, ${TESS_FIXED_WORDS.emitArgs}>` },
});
export type TessBinding = keyof typeof TESS_GROUP.binding;
export const TESS_BINDINGS = Object.keys(TESS_GROUP.binding) as TessBinding[];
/** What any evaluation over the mesh reads (no outputs): e.g. src/gpu/cc/sample.ts. */
export const TESS_INPUTS: readonly TessBinding[] = ['params', 'staticBuf', 'cageBuf', 'work'];

/** Group 0 of the surface sampler's kernel (src/gpu/tess/sample-surface.ts), after TESS_INPUTS:
 * its points in and its (position, normal) results out. */
export const TESS_SAMPLE_GROUP = defineBindGroup(0, {
  samples: { binding: 4, space: 'read', type: 'array<u32>', doc: '(t, w1, w2) per point' },
  results: { binding: 5, space: 'read_write', type: 'array<f32>', doc: '(position, normal) per point' },
});

/** WGSL of TESS_SCANS, for wgsl/tess/scan.wgsl: lane kind i's input, output and length. */
export function scanLanesWgsl(): string {
  const cases = (f: (sc: (typeof TESS_SCANS)[number]) => string) =>
    TESS_SCANS.map((sc, i) => `    case ${i}u: { return ${f(sc)}; }`).join('\n');
  const fn = (name: string, f: (sc: (typeof TESS_SCANS)[number]) => string) =>
    `fn ${name}(kind: u32) -> u32 {\n  switch (kind) {\n${cases(f)}\n    default: { return 0u; }\n  }\n}`;
  const cap = (n: string) => n[0].toUpperCase() + n.slice(1);
  return [
    fn('scanLaneIn', (sc) => `params.off${cap(sc.from)}`),
    fn('scanLaneOut', (sc) => `params.off${cap(sc.to)}`),
    fn('scanLaneLength', (sc) => (sc.over === 'edges' ? 'params.nEdges' : 'params.nTris')),
  ].join('\n');
}
