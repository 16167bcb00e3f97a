/**
 * What fills the mesh buffers the renderer draws. Both sources produce a `TessellatedMesh`:
 *  - `CageGeometry`: the cage itself, fan-triangulated (the "before" view and a fallback);
 *  - `TessellatorGeometry`: the compute tessellator (Phong, Catmull-Clark or an ACC scheme),
 *    rebuilt when the camera, factors or model change.
 */
import type { Cage } from '../mesh/types.ts';
import type { FactorParams, TessellatedMesh } from '../gpu/types.ts';
import { destroyMesh, uploadCageMesh } from '../gpu/cage-mesh.ts';
import { prepareMesh, Tessellator } from '../gpu/tessellator.ts';
import { bakeTables } from '../pattern/tables.ts';
import type { CatmullClarkData } from '../gpu/cc/build.ts';
import { isAccSurface, type Surface } from '../gpu/tess-passes.ts';
import { prepareAccSurface, type AccSurface } from '../gpu/acc-surface.ts';
import { prepareDisplacement, type DisplacementSettings } from '../gpu/displacement.ts';
import type { PreparedMesh } from '../gpu/prepare.ts';
import type { HeightMap, HeightWrap } from '../mesh/heightmap.ts';

/** A height map over a cage's uvs, and how it is addressed outside [0, 1]. */
export interface CageHeightMap {
  map: HeightMap;
  wrap: HeightWrap;
}

export type TessSurface = Surface;

export interface GeometrySource {
  readonly kind: 'cage' | 'tessellator';
  /** The buffers to draw (null before the first model). */
  readonly output: TessellatedMesh | null;
  /** Upload a new model (with its Catmull-Clark tables for that surface). Throws (with a
   * message fit to show) if it cannot be used. */
  setCage(cage: Cage, cc?: CatmullClarkData): void;
  /** Encode a rebuild of `output` for these factors. */
  encode(encoder: GPUCommandEncoder, params: FactorParams): void;
  /** Whether `encode` depends on the camera (adaptive factors) or only on the factors. */
  dependsOnCamera(params: Pick<FactorParams, 'mode'>): boolean;
  readTimings(): Promise<Record<string, number>>;
  destroy(): void;
}

export class CageGeometry implements GeometrySource {
  readonly kind = 'cage';
  output: TessellatedMesh | null = null;
  readonly #device: GPUDevice;

  constructor(device: GPUDevice) {
    this.#device = device;
  }

  setCage(cage: Cage): void {
    if (this.output) destroyMesh(this.output);
    this.output = uploadCageMesh(this.#device, cage);
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
    if (this.output) destroyMesh(this.output);
    this.output = null;
  }
}

/** Largest tess factor of the baked pattern tables. */
const MAX_FACTOR = 64;

let bakedTables: Uint32Array | null = null;

export class TessellatorGeometry implements GeometrySource {
  readonly kind = 'tessellator';
  readonly surface: TessSurface;
  readonly #tessellator: Tessellator;
  readonly #device: GPUDevice;
  /** An ACC surface's patches for the cage shown (made at setCage, this object's to free). */
  #acc: AccSurface | undefined;
  #hasMesh = false;
  /** What the cage shown was set with, so a height map can be added to it (setHeightMap). */
  #last: { cage: Cage; prepared: PreparedMesh; cc?: CatmullClarkData; height: CageHeightMap | null } | null = null;

  constructor(device: GPUDevice, capacity: number, surface: TessSurface = 'phong') {
    this.#device = device;
    // The tables are baked in JavaScript from the same pattern code the tests check (~50 ms), once.
    bakedTables ??= bakeTables(MAX_FACTOR);
    this.surface = surface;
    this.#tessellator = Tessellator.create(device, bakedTables, { vertexCapacity: capacity, triangleCapacity: capacity, surface });
  }

  /** Catmull-Clark: the flat-baseline blend at low tess factors (Tessellator.flatBaseline). */
  get flatBaseline(): boolean {
    return this.#tessellator.flatBaseline;
  }

  set flatBaseline(on: boolean) {
    this.#tessellator.flatBaseline = on;
  }

  get output(): TessellatedMesh | null {
    return this.#hasMesh ? this.#tessellator.output : null;
  }

  /** An ACC scheme throws AccError (a message fit to show) for a cage it does not take; the
   * cage shown before is then gone too, and the caller shows another surface. */
  setCage(cage: Cage, cc?: CatmullClarkData, height: CageHeightMap | null = null): void {
    this.#hasMesh = false;
    this.#last = null;
    const prepared = prepareMesh(cage);
    const acc = isAccSurface(this.surface) ? prepareAccSurface(this.#device, cage, prepared, this.surface) : undefined;
    this.#acc?.patches.destroy();
    this.#acc = acc;
    this.#tessellator.setMesh(prepared, cc, acc, height ? prepareDisplacement(cage, prepared, height.map, height.wrap) : undefined);
    this.#last = { cage, prepared, cc, height };
    this.#hasMesh = true;
  }

  /** A height map for the cage shown (null: none): its uvs and texels go to the GPU again
   * (the topology is not redone). Throws (a CageError naming the face) without uvs. */
  setHeightMap(cage: Cage, height: CageHeightMap | null): void {
    const last = this.#last;
    if (!last || last.cage !== cage || last.height === height) return;
    const disp = height ? prepareDisplacement(cage, last.prepared, height.map, height.wrap) : undefined;
    this.#tessellator.setMesh(last.prepared, last.cc, this.#acc, disp);
    last.height = height;
  }

  /** Scale, mid level, on/off: uniforms only. */
  setDisplacement(settings: Partial<DisplacementSettings>): void {
    this.#tessellator.setDisplacement(settings);
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

  destroy(): void {
    this.#tessellator.destroy();
    this.#acc?.patches.destroy();
    this.#acc = undefined;
  }
}
