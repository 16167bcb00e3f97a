/**
 * What fills the mesh buffers the renderer draws. Both sources produce a `TessellatedMesh`:
 *  - `CageGeometry`: the cage itself, fan-triangulated (the "before" view and a fallback);
 *  - `TessellatorGeometry`: the compute tessellator, rebuilt when the camera, factors or model change.
 */
import type { Cage } from '../mesh/types.ts';
import type { FactorParams, TessellatedMesh } from '../gpu/types.ts';
import { destroyMesh, uploadCageMesh } from '../gpu/cage-mesh.ts';

export interface GeometrySource {
  readonly kind: 'cage' | 'tessellator';
  /** The buffers to draw (null before the first model). */
  readonly output: TessellatedMesh | null;
  /** Upload a new model. Throws (with a message fit to show) if it cannot be used. */
  setCage(cage: Cage): void;
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

/** The page's geometry source: the flat cage until the compute tessellator lands. */
export async function createGeometry(device: GPUDevice, _capacity: number): Promise<GeometrySource> {
  return new CageGeometry(device);
}
