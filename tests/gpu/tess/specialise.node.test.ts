/**
 * The passes that evaluate the surface are compiled per mesh with the surface's override values
 * (SurfaceScheme.specialise: wgsl/cc/surface.wgsl CC_NGONS, CC_CREASE_PATCHES, CC_PHANTOMS,
 * CC_ODD_SLICES) and
 * the tessellator's options (FLAT_BASELINE, DISPLACED): what they compile out is code the mesh
 * never runs, so the output is the general evaluator's, word for word. The values themselves are
 * held to what each cage has by tests/gpu/surface/registry.test.ts.
 */
import { afterAll, describe, expect, it } from 'vitest';
import torusObj from '../../../public/models/torus.obj?raw';
import creatureObj from '../../../public/models/creature.obj?raw';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { tessellateCC } from '../../support/cc-checks.ts';
import { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { surfaceScheme } from '../../../src/gpu/surface/registry.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import { loadCage } from '../../../src/mesh/index.ts';

const made: Tessellator[] = [];
afterAll(() => {
  for (const t of made) t.destroy();
  return releaseDevice();
});

describe('a surface compiled for the mesh', () => {
  // torus: every value 0 (quads, closed, no creases); creature: n-gons, no phantoms or creases
  // (its extraordinary vertices' sectors run in both). Adaptive, so the flat blend runs too.
  it.each([
    ['torus', torusObj, { CC_NGONS: 0, CC_CREASE_PATCHES: 0, CC_PHANTOMS: 0, CC_ODD_SLICES: 0 }],
    ['creature', creatureObj, { CC_NGONS: 1, CC_CREASE_PATCHES: 0, CC_PHANTOMS: 0, CC_ODD_SLICES: 0 }],
  ])(
    '%s: the same output as the general evaluator, word for word',
    async (_name, obj, values) => {
      const device = await getDevice();
      const cage = loadCage(obj).cage;
      const mesh = prepareMesh(cage);
      const cc = buildCatmullClark(cage, mesh);
      expect(surfaceScheme('catmull-clark').specialise({ cc })).toEqual(values);
      const tables = bakeTables(64);
      const out = [];
      for (const specialise of [true, false]) {
        const t = Tessellator.create(device, tables, {
          surface: 'catmull-clark',
          vertexCapacity: 1 << 17,
          triangleCapacity: 1 << 18,
          specialise,
        });
        made.push(t);
        out.push(await tessellateCC(device, t, mesh, cc, testCamera(mesh, 1.2 * mesh.size, undefined, 2)));
      }
      const [a, b] = out;
      expect(a.vertexCount).toBeGreaterThan(1000);
      expect([a.vertexCount, a.triangleCount]).toEqual([b.vertexCount, b.triangleCount]);
      const words = (f: Float32Array | Uint32Array, n: number) => new Uint32Array(f.buffer, f.byteOffset, n);
      expect(words(a.positions, 3 * a.vertexCount)).toEqual(words(b.positions, 3 * b.vertexCount));
      expect(words(a.normals, 3 * a.vertexCount)).toEqual(words(b.normals, 3 * b.vertexCount));
      expect(words(a.indices, 3 * a.triangleCount)).toEqual(words(b.indices, 3 * b.triangleCount));
    },
    60_000,
  );
});
