/**
 * The ACC schemes as the compute tessellator's surface (Tessellator surface 'bezier-acc' |
 * 'gregory-acc' | 'pm-acc', src/gpu/acc/surface.ts, wgsl/acc/surface-tess.wgsl): on every
 * project model (those with n-gons after one Catmull-Clark step: src/subdiv/acc.ts accCage), each output vertex against the f64 ACC yardstick
 * (src/subdiv/acc.ts AccSurface) at the same (face, u, v) (src/gpu/acc/patches.ts accFaceParam): within
 * 2e-6 of the diagonal (f32, as tests/gpu/acc/acc.gpu.test.ts), and the tessellator's own checks (the
 * CPU pattern's counts, watertight after the weld on closed cages, no NaN).
 */
import { describe, it, expect, afterAll } from 'vitest';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { checkTessellation } from '../../support/tess-checks.ts';
import { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { readBuffer, readMesh } from '../../../src/gpu/device/readback.ts';
import { prepareAccSurface } from '../../../src/gpu/acc/surface.ts';
import { accFaceParam } from '../../../src/gpu/acc/patches.ts';
import { ACC_SCHEMES, accCage } from '../../../src/subdiv/acc.ts';
import { AccSurface } from '../../../src/subdiv/acc-evaluate.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import { loadCage } from '../../../src/mesh/index.ts';
import creature from '../../../public/models/creature.obj?raw';
import torus from '../../../public/models/torus.obj?raw';
import creasedBox from '../../../public/models/creased-box.obj?raw';
import sheet from '../../../public/models/sheet.obj?raw';
import icosphere from '../../../public/models/icosphere.obj?raw';
import gear from '../../../public/models/gear.obj?raw';

const POSITION_TOL = 2e-6; // × the model size (bbox diagonal)
const NORMAL_TOL_RAD = (0.05 * Math.PI) / 180;

const tables = bakeTables(64);
const made: Tessellator[] = [];
afterAll(() => {
  made.forEach((t) => t.destroy());
  return releaseDevice();
});

const models: [string, string, boolean][] = [
  ['creature', creature, true],
  ['torus', torus, true],
  ['creased-box', creasedBox, true],
  ['sheet', sheet, false],
  // n-gons: refined once first (accCage); the patches and the reference are the refined cage's.
  ['icosphere', icosphere, true],
  ['gear', gear, true],
];

describe('ACC surfaces in the compute tessellator', () => {
  for (const scheme of ACC_SCHEMES) {
    it(`${scheme}: every output vertex on the f64 ACC surface, watertight, on the project's ACC models`, async () => {
      const device = await getDevice();
      const tess = Tessellator.create(device, tables, { surface: scheme, vertexCapacity: 1 << 19, triangleCapacity: 1 << 19 });
      made.push(tess);
      for (const [name, text, closed] of models) {
        const cage = accCage(loadCage(text).cage).cage;
        const mesh = prepareMesh(cage);
        const acc = prepareAccSurface(device, cage, mesh, scheme);
        const cpu = new AccSurface(cage, scheme);
        device.pushErrorScope('validation');
        tess.setMesh(mesh, undefined, acc);
        const enc = device.createCommandEncoder();
        tess.encode(enc, testCamera(mesh, 1.5 * mesh.size, 5.5));
        device.queue.submit([enc.finish()]);
        const out = await readMesh(device, tess.output);
        const edgeF = new Uint32Array(await readBuffer(device, tess.workBuffer, 4 * mesh.edgeCount, 4 * tess.workLayout.edgeF));
        expect((await device.popErrorScope())?.message).toBeUndefined();
        const report = checkTessellation(mesh, edgeF, out, {
          closed,
          // The ACC schemes' creases (sharpness ≥ 1) are output once per side.
          split: mesh.accSplit,
          reference: (t, w) => {
            const [f, u, v] = accFaceParam(mesh, cage, t, w);
            const r = cpu.evaluate(f, u, v);
            return { pos: r.P, normal: r.N };
          },
        });
        console.log(
          scheme,
          name,
          out.triangleCount,
          report.maxPositionError.toExponential(2),
          ((report.maxNormalError * 180) / Math.PI).toFixed(4),
        );
        expect(report.problems, name).toEqual([]);
        expect(report.maxPositionError, name).toBeLessThan(POSITION_TOL);
        expect(report.maxNormalError, name).toBeLessThan(NORMAL_TOL_RAD);
        acc.patches.destroy();
      }
    }, 300_000);
  }
});
