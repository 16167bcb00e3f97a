/**
 * The contents of the compute tessellator's arenas (contract/tess.ts TESS_STATIC, TESS_CAGE,
 * TESS_WORK) for one mesh: what they are sized from, and the static and cage words packed where
 * their layouts put each array, and the Params fields that say where the arrays lie and how
 * large the mesh is. Tessellator.setMesh (tessellator.ts) packs through packArenas and meshParams,
 * then uploads them.
 */
import type { CatmullClarkData } from '../cc/build.ts';
import type { AccSurface } from '../acc/surface.ts';
import type { DisplacementData } from './displacement-map.ts';
import type { ArenaLayout } from '../contract/define.ts';
import { CC_NO_WORDS, CC_STATIC } from '../contract/cc.ts';
import { TESS_CAGE, type TESS_PARAMS, TESS_STATIC, TESS_WORK, type TessSizes } from '../contract/tess.ts';
import { type CreaseSplit, fannedRoundCentre, type PreparedMesh } from './prepare.ts';
import type { Cage } from '../../mesh/types.ts';

export type WorkName = (typeof TESS_WORK.names)[number];
export type CageName = (typeof TESS_CAGE.names)[number];
export type StaticName = (typeof TESS_STATIC.names)[number];

/** What one mesh's arenas hold, as the tessellator has it. */
export interface PackInput {
  prepared: PreparedMesh;
  /** The Catmull-Clark tables, with that surface. */
  cc: CatmullClarkData | undefined;
  /** The ACC patches, with an ACC surface. */
  acc: AccSurface | undefined;
  disp: DisplacementData | undefined;
  /** The pattern tables' words, and their largest factor. */
  tables: Uint32Array;
  maxFactor: number;
  /** Where the surface's normals split (prepare.ts splitCreases; the Catmull-Clark surface's or the
   * ACC schemes'), if anywhere, and then its extra output vertices of crease and corner vertices. */
  split: CreaseSplit | undefined;
  extraSlots: number;
}

/** The arenas' sizes and layouts for one mesh, and the static and cage words (the work arena is
 * scratch: laid out only). */
export interface PackedArenas {
  sizes: TessSizes;
  staticLayout: ArenaLayout<StaticName>;
  staticWords: Uint32Array;
  cageLayout: ArenaLayout<CageName>;
  cageWords: Float32Array;
  workLayout: ArenaLayout<WorkName>;
}

/** Sizes every arena from the mesh and packs the static and cage words. */
export function packArenas(input: PackInput): PackedArenas {
  const { prepared, cc, acc, disp } = input;
  const split = input.split;
  const sizes: TessSizes = {
    vertices: prepared.vertexCount,
    extraSlots: input.extraSlots,
    edges: prepared.edgeCount,
    triangles: prepared.triangleCount,
    maxFactor: input.maxFactor,
    tableWords: input.tables.length,
    ccWords: cc?.words.length ?? 0,
    ccPoints: cc?.pointCount ?? 0,
    limitVertices: cc ? prepared.vertexCount : 0,
    accTriangles: acc ? prepared.triangleCount : 0,
    accPatchWords: acc?.patches.topology.patches.length ?? 0,
    accPoints: acc?.patches.topology.nPoints ?? 0,
    heightWords: disp?.heightTexels.length ?? 0,
    dispTriangles: disp ? prepared.triangleCount : 0,
    dispEdges: disp ? prepared.edgeCount : 0,
    cornerUvs: disp ? disp.cornerUvs.length / 2 : 0,
  };

  const staticLayout = TESS_STATIC.layout(sizes);
  const staticWords = packArena(TESS_STATIC.names, staticLayout, new Uint32Array(staticLayout.words), {
    tables: input.tables,
    triVerts: prepared.triVerts,
    triEdges: prepared.triEdges,
    triPatternFrame: prepared.triPatternFrame,
    edgeVerts: prepared.edgeVerts,
    edgeOwner: prepared.edgeOwner,
    edgeTwin: prepared.edgeTwin,
    vertexOwner: prepared.vertexOwner,
    cornerSlot: split ? split.cornerSlot : prepared.triVerts,
    slotOwner: split?.slotOwner,
    edgeSplit: split?.edgeSplit,
    cc: cc?.words,
    accTri: acc?.triangles,
    accPatches: acc?.patches.topology.patches,
    heightTexels: disp?.heightTexels,
    dispTri: disp?.dispTri,
    dispEdge: disp?.dispEdge,
  });
  const cageLayout = TESS_CAGE.layout(sizes);
  // The refined points and the limits are written by the patch build.
  const cageWords = packArena(TESS_CAGE.names, cageLayout, new Float32Array(cageLayout.words), {
    positions: prepared.positions,
    normals: prepared.normals,
    phongAlpha: prepared.triPhongAlpha,
    cornerUvs: disp?.cornerUvs,
  });
  const workLayout = TESS_WORK.layout(sizes);
  return { sizes, staticLayout, staticWords, cageLayout, cageWords, workLayout };
}

/** The Params fields of one mesh: its counts, the output's capacity, where each arena's arrays
 * lie, what the factor rule reads, the Catmull-Clark tables' offsets and the height map's shape
 * (the displacement's scale and switch are the tessellator's settings, written apart). */
export function meshParams(
  input: PackInput,
  packed: PackedArenas,
  capacity: { vertexCapacity: number; triangleCapacity: number },
): Parameters<typeof TESS_PARAMS.write>[1] {
  const { prepared, cc, disp } = input;
  const { sizes, staticLayout, cageLayout, workLayout } = packed;
  const ccBase = staticLayout.offset.cc;
  return {
    nVerts: prepared.vertexCount,
    nSlots: prepared.vertexCount + sizes.extraSlots,
    nTris: prepared.triangleCount,
    nEdges: prepared.edgeCount,
    maxFactor: input.maxFactor,
    vertexCapacity: capacity.vertexCapacity,
    triangleCapacity: capacity.triangleCapacity,
    ...TESS_STATIC.offsets(staticLayout),
    ...TESS_CAGE.offsets(cageLayout),
    ...TESS_WORK.offsets(workLayout),
    offFactorPos: cc ? cageLayout.offset.limitPositions : cageLayout.offset.positions,
    offFactorNormal: cc ? cageLayout.offset.limitNormals : cageLayout.offset.normals,
    ccCageVerts: cc?.cageVertexCount ?? 0,
    ...CC_STATIC.offsets(cc?.layout ?? CC_STATIC.layout(CC_NO_WORDS), ccBase),
    nFans: cc?.fanCount ?? 0,
    ccSliceGroups: cc?.sliceWorkgroups ?? 0,
    ccMaxDepth: cc?.maxDepth ?? 0,
    dispBits: disp?.map.bits ?? 8,
    dispWidth: disp?.map.width ?? 1,
    dispHeight: disp?.map.height ?? 1,
    dispWrap: disp?.wrap === 'clamp' ? 1 : 0,
  };
}

/** Copy each array of `sources` to its place in an arena; an array not given stays zero (its
 * length is checked against the layout's when given). */
function packArena<K extends string, T extends Uint32Array | Float32Array>(
  names: readonly K[],
  layout: { offset: Record<K, number>; length: Record<K, number> },
  into: T,
  sources: Partial<Record<K, ArrayLike<number>>>,
): T {
  for (const k of names) {
    const src = sources[k];
    if (!src) continue;
    if (src.length !== layout.length[k]) throw new Error(`arena array ${k}: ${src.length} words given, ${layout.length[k]} laid out`);
    into.set(src, layout.offset[k]);
  }
  return into;
}

/**
 * A lower bound of the work arena's bytes for a cage, from its face sizes alone: the triangles
 * prepare.ts cuts its faces into (holes left out, though they may count) and 3/2 edges a triangle
 * (an edge borders at most two). A caller compares it with the device's binding limit before the
 * CPU preparation, which for a cage of a million quads takes most of a minute and gigabytes before
 * the exact size is known.
 */
export function workBytesAtLeast(cage: Cage, maxFactor: number): number {
  const holes = new Set(cage.holes);
  let triangles = 0;
  for (let f = 0; f < cage.faceOffsets.length - 1; f++) {
    if (holes.has(f)) continue;
    const n = cage.faceOffsets[f + 1] - cage.faceOffsets[f];
    triangles += fannedRoundCentre(n) ? n : n - 2;
  }
  const sizes: TessSizes = {
    vertices: 0,
    extraSlots: 0,
    edges: Math.ceil((3 * triangles) / 2),
    triangles,
    maxFactor,
    tableWords: 0,
    ccWords: 0,
    ccPoints: 0,
    limitVertices: 0,
    accTriangles: 0,
    accPatchWords: 0,
    accPoints: 0,
    heightWords: 0,
    dispTriangles: 0,
    dispEdges: 0,
    cornerUvs: 0,
  };
  return 4 * TESS_WORK.layout(sizes).words;
}

/**
 * A cage the device cannot tessellate, refused from its counts alone (the lower bound of its
 * scratch buffer, workBytesAtLeast above) before any of the preparation that, for
 * a cage of a million quads, takes most of a minute: the sentence to show (the demo's message, the
 * CLI's error), or null when it may fit.
 */
export function cageTooLarge(cage: Cage, maxFactor: number, bindingLimit: number): string | null {
  const bytes = workBytesAtLeast(cage, maxFactor);
  if (bytes <= bindingLimit) return null;
  const faces = cage.faceOffsets.length - 1;
  const n = (x: number) => Math.floor(x).toLocaleString('en-US');
  // Its bytes grow with the faces (per triangle of the fan), so the faces that fit scale with it.
  return `${n(faces)} faces: this device tessellates cages of up to about ${n((faces * bindingLimit) / bytes)} faces at factors up to ${maxFactor} (a storage buffer holds ${n(bindingLimit / 2 ** 20)} MiB; this cage needs ${n(bytes / 2 ** 20)} MiB).`;
}
