/**
 * The surfaces the tessellators evaluate, behind one interface, as OpenSubdiv's schemes plug into
 * its patch builder: Phong tessellation, the exact Catmull-Clark limit, and the three ACC
 * approximations of that limit (Bezier, Gregory, Pm). A tessellator, a sampler or an error view
 * asks its surface what it needs (the evaluator's WGSL, the per-frame patch build, whether it is
 * the exact limit, what it prepares from a cage) and never tells surfaces apart by name: this file
 * is the one place where the names are told apart (tests/gpu/surface/registry.test.ts holds the
 * rest of src/ to that).
 *
 * Each surface's evaluator defines `evalSurface(t, w)` (the point and normal at barycentric
 * weights w of prepared triangle t) over the compute tessellator's bindings: Phong reads the cage
 * arena only; the Catmull-Clark limit also reads the refined points and limits that its patch
 * build writes into the work arena every frame; an ACC scheme reads its patches' control points,
 * which AccPatches rebuilds from the cage every frame.
 */
import phongSurfaceWgsl from '../../../wgsl/surface/phong.wgsl?raw';
import accTessWgsl from '../../../wgsl/acc/surface-tess.wgsl?raw';
import type { Cage } from '../../mesh/types.ts';
import { ACC_SCHEMES, type AccScheme, accCage } from '../../subdiv/acc.ts';
import { CC_SURFACE_WGSL } from '../cc/shaders.ts';
import { buildCatmullClark, type CatmullClarkData } from '../cc/build.ts';
import { ACC_SURFACE_WGSL } from '../acc/patches.ts';
import { prepareAccSurface, type AccSurface } from '../acc/surface.ts';
import type { PreparedMesh } from '../tess/prepare.ts';
import type { InstancedSurfaceKind } from '../instanced/instanced-options.ts';

export type SurfaceId = 'phong' | 'catmull-clark' | AccScheme;

/** What a surface prepares from a cage once per model: the tables or patches its evaluator reads
 * (none for Phong). The GPU objects in it (ACC patches) are released with releaseSurfaceData. */
export interface SurfaceData {
  cc?: CatmullClarkData;
  acc?: AccSurface;
}

/** The cage a surface tessellates (SurfaceScheme.surfaceCage). */
export interface SurfaceCage {
  cage: Cage;
  /** Why it is not the cage given (what the stats and the CLI say), or null when it is. */
  note: string | null;
  /** Catmull-Clark steps from the cage given (each halves its edges): 0 when it is the same. */
  steps: number;
}

const sameCage = (cage: Cage): SurfaceCage => ({ cage, note: null, steps: 0 });

export interface SurfaceScheme {
  readonly id: SurfaceId;
  /** As the panel, the stats and the messages name it. */
  readonly name: string;
  /** Defines `evalSurface(t, w)` over the compute tessellator's bindings (after its prelude and
   * wgsl/tess/common.wgsl). */
  readonly tessWgsl: string;
  /** What rebuilds its control points from the cage every frame: 'refinement', the tessellator's
   * own Catmull-Clark passes (refined points and limits into the work arena); 'acc-patches',
   * AccPatches' build pass; 'none' (Phong reads the cage itself). */
  readonly patchBuild: 'none' | 'refinement' | 'acc-patches';
  /** The exact Catmull-Clark limit surface: the reference every error view measures against, and
   * the only surface whose buffers the instanced tessellator borrows. */
  readonly exactLimit: boolean;
  /** Where its normals split, because the surface has a crease there: at infinitely sharp creases
   * and corners (the limit surface), at those of sharpness ≥ 1 (the ACC schemes, which build them
   * infinitely sharp: their patches meet there at an angle, and one output vertex per point gave
   * the far side's triangles the near side's normal), or nowhere (Phong: one normal per cage vertex,
   * so both sides would be the same). prepare.ts splitCreases makes both splits. */
  readonly splitsCreases: false | 'infinitely-sharp' | 'sharpness-1';
  /** Its evaluator reads the tessellator's work arena (the patch build's output). */
  readonly readsWork: boolean;
  /** Its evaluator blends from the flat triangle of the corners' limit points where the tess
   * factors are low, when TessellatorOptions.flatBaseline asks (the other surfaces ignore it). */
  readonly flatBaseline: boolean;
  /** How the instanced tessellator's vertex stage evaluates it: its own cage buffer (evalSurface),
   * AccPatches' control points, or the buffers of a compute tessellator on the exact limit. */
  readonly instancedKind: InstancedSurfaceKind;
  /** The values of its evaluator's override constants for this data: which of the surface's cases
   * the cage has, so that the passes that evaluate it are compiled without the others (the
   * tessellator makes them per mesh: src/gpu/tess/pipelines.ts). {} for the general evaluator. */
  specialise(data: SurfaceData): Record<string, number>;
  /** The cage its tessellation is made on, from the cage given: the same cage, or one that the
   * surface takes in its place with the same limit (the ACC schemes refine a cage with n-gons
   * once: src/subdiv/acc.ts accCage). A tessellator prepares (prepareMesh, prepare) the cage this
   * returns; its output's triangles and faces are that cage's. */
  surfaceCage(cage: Cage): SurfaceCage;
  /** Whether the data has what this surface's evaluator reads. */
  hasData(data: SurfaceData): boolean;
  /** The tables or patches for a prepared cage (one that surfaceCage returned). Throws, with the
   * reason, on a cage the surface refuses (an ACC scheme: n-gons not refined, holes; the
   * Catmull-Clark build: sharpness beyond its levels). */
  prepare(device: GPUDevice, cage: Cage, mesh: PreparedMesh): SurfaceData;
}

const phong: SurfaceScheme = {
  id: 'phong',
  name: 'Phong',
  tessWgsl: phongSurfaceWgsl,
  patchBuild: 'none',
  exactLimit: false,
  splitsCreases: false,
  readsWork: false,
  flatBaseline: false,
  instancedKind: 'evalSurface',
  specialise: () => ({}),
  surfaceCage: sameCage,
  hasData: () => true,
  prepare: () => ({}),
};

const catmullClark: SurfaceScheme = {
  id: 'catmull-clark',
  name: 'Catmull-Clark',
  tessWgsl: CC_SURFACE_WGSL,
  patchBuild: 'refinement',
  exactLimit: true,
  splitsCreases: 'infinitely-sharp',
  readsWork: true,
  flatBaseline: true,
  instancedKind: 'lent-limit',
  // wgsl/cc/surface.wgsl: n-gons (their kite parametrisation), single-crease patches (their
  // basis), phantom points (boundaries and infinitely sharp edges), fans keeping their odd steps
  // only (an even step's sub-patch made again).
  specialise: ({ cc }): Record<string, number> =>
    cc
      ? {
          CC_NGONS: +cc.hasNgons,
          CC_CREASE_PATCHES: +(cc.singleCreaseCount > 0 || cc.semiAxes),
          CC_PHANTOMS: +cc.hasPhantoms,
          CC_ODD_SLICES: +cc.oddSlices,
        }
      : {},
  surfaceCage: sameCage,
  hasData: (data) => data.cc !== undefined,
  prepare: (_device, cage, mesh) => ({ cc: buildCatmullClark(cage, mesh) }),
};

const ACC_NAMES: Record<AccScheme, string> = { 'bezier-acc': 'Bezier ACC', 'gregory-acc': 'Gregory ACC', 'pm-acc': 'Pm ACC' };

function accScheme(scheme: AccScheme): SurfaceScheme {
  return {
    id: scheme,
    name: ACC_NAMES[scheme],
    tessWgsl: [ACC_SURFACE_WGSL, accTessWgsl].join('\n'),
    patchBuild: 'acc-patches',
    exactLimit: false,
    splitsCreases: 'sharpness-1',
    readsWork: false,
    flatBaseline: false,
    instancedKind: 'acc',
    specialise: () => ({}),
    surfaceCage: accCage,
    hasData: (data) => data.acc?.patches.scheme === scheme,
    prepare: (device, cage, mesh) => ({ acc: prepareAccSurface(device, cage, mesh, scheme) }),
  };
}

/** Every surface, in the order the panel lists them. */
export const SURFACE_SCHEMES: readonly SurfaceScheme[] = [catmullClark, phong, ...ACC_SCHEMES.map(accScheme)];
export const SURFACE_IDS: readonly SurfaceId[] = SURFACE_SCHEMES.map((s) => s.id);

const byId = new Map<string, SurfaceScheme>(SURFACE_SCHEMES.map((s) => [s.id, s]));

/** The surface of that id; throws on an unknown one (a URL parameter, a CLI flag). */
export function surfaceScheme(id: SurfaceId): SurfaceScheme {
  const s = byId.get(id);
  if (!s) throw new Error(`unknown surface '${id}' (one of ${SURFACE_IDS.join(', ')})`);
  return s;
}

/** Whether a string names a surface. */
export function isSurfaceId(id: string): id is SurfaceId {
  return byId.has(id);
}

/** Whether the surface approximates the Catmull-Clark limit with patches (an ACC scheme): what the
 * error views measure. */
export function isAccSurface(id: SurfaceId): id is AccScheme {
  return surfaceScheme(id).patchBuild === 'acc-patches';
}

/** Release the GPU objects a SurfaceData holds (ACC patches); the tables are plain arrays. */
export function releaseSurfaceData(data: SurfaceData): void {
  data.acc?.patches.destroy();
}
