/**
 * What fills the mesh buffers the renderer draws. Both sources produce a `TessellatedMesh`:
 *  - `CageGeometry`: the cage itself, fan-triangulated (the "before" view and a fallback);
 *  - `TessellatorGeometry`: the compute tessellator (Phong, Catmull-Clark or an ACC scheme),
 *    rebuilt when the camera, factors or model change.
 */
import type { Cage } from '../mesh/types.ts';
import type { FactorParams, TessellatedMesh } from '../gpu/contract/tessellated-mesh.ts';
import { destroyMesh, uploadCageMesh, type TriangulatedCage } from '../gpu/render/cage-mesh.ts';
import { prepareMesh, Tessellator } from '../gpu/tess/tessellator.ts';
import type { TessPipelines } from '../gpu/tess/pipelines.ts';
import { bakeTables } from '../pattern/tables.ts';
import { MAX_FACTOR } from '../pattern/max-factor.ts';
import type { CatmullClarkData } from '../gpu/cc/build.ts';
import { isAccSurface, type SurfaceCage, type SurfaceId as Surface, surfaceScheme } from '../gpu/surface/registry.ts';
import { accPatchKinds, prepareAccSurface, type AccSurface } from '../gpu/acc/surface.ts';
import type { AccPatches } from '../gpu/acc/patches.ts';
import { prepareDisplacement, type DisplacementSettings } from '../gpu/tess/displacement-map.ts';
import type { PreparedMesh } from '../gpu/tess/prepare.ts';
import type { HeightMap, HeightWrap } from '../mesh/heightmap.ts';

/** A height map over a cage's uvs, and how it is addressed outside [0, 1]. */
export interface CageHeightMap {
  map: HeightMap;
  wrap: HeightWrap;
}

export type TessSurface = Surface;

/** What the renderer draws from: the flat cage or a tessellator (each takes a model by its own
 * setCage, with what it needs). */
export interface GeometrySource {
  readonly kind: 'cage' | 'tessellator';
  /** The buffers to draw (null before the first model). */
  readonly output: TessellatedMesh | null;
  /** Encode a rebuild of `output` for these factors. */
  encode(encoder: GPUCommandEncoder, params: FactorParams): void;
  /** Whether `encode` depends on the camera (adaptive factors) or only on the factors. */
  dependsOnCamera(params: Pick<FactorParams, 'mode'>): boolean;
  readTimings(): Promise<Record<string, number>>;
  /** The timestamps' readback never settled: its builds go untimed (src/gpu/device/map-within.ts). */
  readonly timingStalled?: boolean;
  /** A build's timestamps wait to be read: it came while the last read was in flight. */
  readonly timingUnread?: boolean;
  destroy(): void;
}

export class CageGeometry implements GeometrySource {
  readonly kind = 'cage';
  readonly #device: GPUDevice;
  #cage: Cage | null = null;
  /** The cage's triangulation where a worker made it (a file's, src/app/model-worker.ts). */
  #triangulated: TriangulatedCage | undefined;
  #output: TessellatedMesh | null = null;

  constructor(device: GPUDevice) {
    this.#device = device;
  }

  /** The cage to draw; triangulated and uploaded when first drawn (a surface shown at once never
   * needs it: on a 40,000-face cage that was 27 ms of the page's thread for nothing). */
  setCage(cage: Cage, triangulated?: TriangulatedCage): void {
    if (cage === this.#cage) return;
    this.#cage = cage;
    this.#triangulated = triangulated;
    if (this.#output) destroyMesh(this.#output);
    this.#output = null;
  }

  get output(): TessellatedMesh | null {
    if (!this.#output && this.#cage) this.#output = uploadCageMesh(this.#device, this.#cage, this.#triangulated);
    return this.#output;
  }

  /** Free the buffers while another surface is shown (the cage stays: drawn again, it is uploaded
   * again). The interim picture of a first load held them for as long as the page lived. */
  release(): void {
    if (this.#output) destroyMesh(this.#output);
    this.#output = null;
  }

  encode(): void {
    // The cage's buffers were filled at upload; there is nothing to rebuild.
  }

  dependsOnCamera(): boolean {
    return false;
  }

  async readTimings(): Promise<Record<string, number>> {
    return {};
  }

  destroy(): void {
    if (this.#output) destroyMesh(this.#output);
    this.#output = null;
    this.#cage = null;
    // A worker's triangulation of a large file is as large as the cage: let it go with it.
    this.#triangulated = undefined;
  }
}

let bakedTables: Uint32Array | null = null;

/** The pattern tables every tessellator of the page uses (baked once, up to the largest factor). */
export function patternTables(): Uint32Array {
  bakedTables ??= bakeTables(MAX_FACTOR);
  return bakedTables;
}

export class TessellatorGeometry implements GeometrySource {
  readonly kind = 'tessellator';
  readonly surface: TessSurface;
  readonly #tessellator: Tessellator;
  readonly #device: GPUDevice;
  /** An ACC surface's patches for the cage shown (made at setCage, this object's to free). */
  #acc: AccSurface | undefined;
  #hasMesh = false;
  /** What the cage shown was set with, so a height map can be added to it (setHeightMap). */
  /** `cage` as given; `tessellated`, the cage the surface tessellates in its place (the same one,
   * or an ACC scheme's refinement of a cage with n-gons): `prepared` is that cage's. */
  #last: { cage: Cage; tessellated: SurfaceCage; prepared: PreparedMesh; cc?: CatmullClarkData; height: CageHeightMap | null } | null =
    null;

  /** `pipelines`: the surface's, compiled before (src/app/tess-pipelines.ts); made now if absent. */
  constructor(device: GPUDevice, capacity: number, surface: TessSurface = 'phong', pipelines?: TessPipelines) {
    this.#device = device;
    // The tables are baked in JavaScript from the same pattern code the tests check (~50 ms), once.
    this.surface = surface;
    this.#tessellator = Tessellator.create(device, patternTables(), {
      vertexCapacity: capacity,
      triangleCapacity: capacity,
      surface,
      pipelines,
    });
  }

  /** Catmull-Clark: the flat-baseline blend at low tess factors (Tessellator.flatBaseline). */
  get flatBaseline(): boolean {
    return this.#tessellator.flatBaseline;
  }

  set flatBaseline(on: boolean) {
    this.#tessellator.flatBaseline = on;
  }

  /** The ACC patches of the cage shown (an ACC surface; rebuilt by every encode), or undefined. */
  get accPatches(): AccPatches | undefined {
    return this.#hasMesh ? this.#acc?.patches : undefined;
  }

  /** The cage the surface tessellates (the cage shown, or the surface's in its place: an ACC
   * scheme refines a cage with n-gons once), and why it is another, for the stats. */
  get tessellatedCage(): SurfaceCage | undefined {
    return this.#hasMesh ? this.#last?.tessellated : undefined;
  }

  /** The cage tessellated (tessellatedCage), prepared (its triangles are the output's srcTri). */
  get prepared(): PreparedMesh | undefined {
    return this.#hasMesh ? this.#tessellator.prepared : undefined;
  }

  get output(): TessellatedMesh | null {
    return this.#hasMesh ? this.#tessellator.output : null;
  }

  /** An ACC scheme throws AccError (a message fit to show) for a cage it does not take; the
   * cage shown before is then gone too, and the caller shows another surface. */
  setCage(cage: Cage, cc?: CatmullClarkData, height: CageHeightMap | null = null, mesh?: PreparedMesh): void {
    this.#hasMesh = false;
    this.#last = null;
    // The cage the surface tessellates (an ACC scheme refines a cage with n-gons once: the mesh
    // and tables prepared for the cage itself are not that cage's then).
    const tessellated = surfaceScheme(this.surface).surfaceCage(cage);
    const own = tessellated.cage !== cage;
    if (own) cc = undefined;
    // Prepared with the exact surface's tables (src/app/surface-data.ts, off the page's thread for
    // a large cage), or here.
    const prepared = (!own && mesh) || prepareMesh(tessellated.cage);
    const acc = isAccSurface(this.surface) ? prepareAccSurface(this.#device, tessellated.cage, prepared, this.surface) : undefined;
    this.#acc?.patches.destroy();
    this.#acc = acc;
    const disp = height ? prepareDisplacement(tessellated.cage, prepared, height.map, height.wrap) : undefined;
    this.#tessellator.setMesh(prepared, cc, acc, disp);
    this.#last = { cage, tessellated, prepared, cc, height };
    this.#hasMesh = true;
  }

  /** A height map for the cage shown (null: none): its uvs and texels go to the GPU again
   * (the topology is not redone). Throws (a CageError naming the face) without uvs. */
  setHeightMap(cage: Cage, height: CageHeightMap | null): void {
    const last = this.#last;
    if (!last || last.cage !== cage || last.height === height) return;
    const disp = height ? prepareDisplacement(last.tessellated.cage, last.prepared, height.map, height.wrap) : undefined;
    this.#tessellator.setMesh(last.prepared, last.cc, this.#acc, disp);
    last.height = height;
  }

  /** Scale, mid level, on/off: uniforms only. */
  setDisplacement(settings: Partial<DisplacementSettings>): void {
    this.#tessellator.setDisplacement(settings);
  }

  /** An ACC surface's patch kind per cage triangle (regular, irregular quad, triangle: the
   * patch colours), or null for the other surfaces. */
  get accPatchKinds(): Uint8Array | null {
    return this.#acc && this.#last ? accPatchKinds(this.#acc, this.#last.prepared) : null;
  }

  /** Whether the output is displaced now. */
  get displaced(): boolean {
    return this.#tessellator.displaced;
  }

  encode(encoder: GPUCommandEncoder, params: FactorParams): void {
    this.#tessellator.encode(encoder, params);
  }

  dependsOnCamera(params: Pick<FactorParams, 'mode'>): boolean {
    return params.mode === 'adaptive';
  }

  readTimings(): Promise<Record<string, number>> {
    return this.#tessellator.readTimings();
  }

  get timingStalled(): boolean {
    return this.#tessellator.timingStalled;
  }

  get timingUnread(): boolean {
    return this.#tessellator.timingUnread;
  }

  destroy(): void {
    this.#tessellator.destroy();
    this.#acc?.patches.destroy();
    this.#acc = undefined;
  }
}
