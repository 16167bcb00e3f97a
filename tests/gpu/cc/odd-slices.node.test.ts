/**
 * Fans that keep their odd steps only (src/gpu/cc/fans.ts SliceSteps 'odd': half the slices'
 * bytes, the memory bound of src/gpu/cc/build.ts SLICE_BUDGET_BYTES_PER_FACE). Their even steps'
 * points are not in memory at all, so a vertex on an even step's sub-patch is right only if the
 * evaluator makes them again (wgsl/cc/surface.wgsl, by wgsl/cc/slices.wgsl ccSliceMake, the slice
 * kernel's own step), and a fan whose last step is even gets its limit only if the limits kernel
 * does the same (wgsl/cc/build.wgsl ringPt). Held here: the output of the odd layout against the
 * every-step layout's (itself held to the CPU reference by tests/gpu/cc/cc.gpu.test.ts), vertex by
 * vertex, at fixed factor 16 (vertices on steps 1-4 of every sector) and adaptive (fractional
 * factors: vertices deeper still). The points made again are the stored ones bit for bit (the
 * same step in the same f32 order); the sum over them runs point by point rather than row by
 * row, so the outputs differ in the last bits (SwiftShader: ≤ 4.4e-8 of the diagonal, normals
 * ≤ 2.4e-7).
 *  - icosphere: triangles, every fan at level 2 (D = 6: the last step is even);
 *  - creased-box: creases, corners and boundaries of sharp fans (phantom points on their axes,
 *    depth + 3), semi-sharp levels;
 *  - sheet: an open grid (boundary fans and their pseudo-sectors).
 */
import { afterAll, describe, expect, it } from 'vitest';
import icosphereObj from '../../../public/models/icosphere.obj?raw';
import creasedBoxObj from '../../../public/models/creased-box.obj?raw';
import sheetObj from '../../../public/models/sheet.obj?raw';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { tessellateCC } from '../../support/cc-checks.ts';
import { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import { loadCage } from '../../../src/mesh/index.ts';

/** Positions: fraction of the bounding-box diagonal; normals: unit vectors, component-wise. */
const POSITION_TOL = 1e-7;
const NORMAL_TOL = 1e-6;

let tess: Tessellator | undefined;
afterAll(() => {
  tess?.destroy();
  return releaseDevice();
});

describe('fans keeping their odd steps only: the even steps made again', () => {
  it.each([
    ['icosphere', icosphereObj],
    ['creased-box', creasedBoxObj],
    ['sheet', sheetObj],
  ])(
    '%s: the output with every step stored, at half the slices',
    async (_name, obj) => {
      const device = await getDevice();
      const cage = loadCage(obj).cage;
      const mesh = prepareMesh(cage);
      const every = buildCatmullClark(cage, mesh, { slices: 'every' });
      const odd = buildCatmullClark(cage, mesh, { slices: 'odd' });
      expect(odd.oddSlices).toBe(true);
      expect(every.oddSlices).toBe(false);
      expect(odd.pointCount).toBeLessThan(every.pointCount);
      tess ??= Tessellator.create(device, bakeTables(64), {
        surface: 'catmull-clark',
        vertexCapacity: 1 << 18,
        triangleCapacity: 1 << 19,
      });
      for (const camera of [testCamera(mesh, 1.5 * mesh.size, 16), testCamera(mesh, 1.2 * mesh.size, undefined, 2)]) {
        const a = await tessellateCC(device, tess, mesh, every, camera);
        const b = await tessellateCC(device, tess, mesh, odd, camera);
        expect(a.vertexCount).toBeGreaterThan(1000);
        expect([b.vertexCount, b.triangleCount]).toEqual([a.vertexCount, a.triangleCount]);
        expect(b.indices.subarray(0, 3 * b.triangleCount)).toEqual(a.indices.subarray(0, 3 * a.triangleCount));
        let dp = 0,
          dn = 0;
        for (let i = 0; i < 3 * a.vertexCount; i++) {
          dp = Math.max(dp, Math.abs(a.positions[i] - b.positions[i]));
          dn = Math.max(dn, Math.abs(a.normals[i] - b.normals[i]));
        }
        expect(Number.isFinite(dp) && Number.isFinite(dn)).toBe(true);
        expect(dp / mesh.size).toBeLessThanOrEqual(POSITION_TOL);
        expect(dn).toBeLessThanOrEqual(NORMAL_TOL);
      }
    },
    120_000,
  );
});
