/**
 * A cage's CPU preparation for the exact surface, one function for the page's thread and the
 * worker (src/app/prepare-worker.ts): the tessellator's mesh and the Catmull-Clark tables built
 * from it, timed. Plain data (typed arrays and numbers), so it crosses to the page by transfer.
 */
import type { Cage } from '../mesh/types.ts';
import { prepareMesh, type PreparedMesh } from '../gpu/tess/prepare.ts';
import { buildCatmullClark, type CatmullClarkData } from '../gpu/cc/build.ts';

export interface SurfaceData {
  /** The cage's triangles, edges and owners (src/gpu/tess/prepare.ts), as every surface's tessellator takes them. */
  mesh: PreparedMesh;
  data: CatmullClarkData;
  /** Wall-clock milliseconds of the preparation (on whichever thread ran it). */
  ms: number;
}

export function prepareSurfaceData(cage: Cage): SurfaceData {
  const t0 = performance.now();
  const mesh = prepareMesh(cage);
  const data = buildCatmullClark(cage, mesh);
  return { mesh, data, ms: performance.now() - t0 };
}
