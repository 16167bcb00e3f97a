/** The tessellator of the demo's default surface, for tests that check what the demo shows:
 * exact Catmull-Clark with the flat-baseline blend, buffers of 2^20 vertices and triangles. One
 * per test file (its pipelines compile once); the caller destroys it. */
import { Tessellator } from '../../src/gpu/tess/tessellator.ts';
import { bakeTables } from '../../src/pattern/tables.ts';

export function demoCcTessellator(device: GPUDevice): Tessellator {
  return Tessellator.create(device, bakeTables(64), {
    surface: 'catmull-clark',
    flatBaseline: true,
    vertexCapacity: 1 << 20,
    triangleCapacity: 1 << 20,
  });
}
