/**
 * The ACC error view's data pass (src/gpu/acc/error.ts) on a real WebGPU adapter: per point, the
 * distance between the ACC surface and the exact Catmull-Clark surface (both evaluated on the GPU)
 * and the angle between their normals, held element by element against the same two quantities
 * from the f64 CPU references (src/subdiv/acc.ts, src/subdiv exact). Tolerance: the sum of the two
 * GPU evaluators' own stated bounds (tests/gpu/cc/cc.gpu.test.ts: 1e-5 of the diagonal, 1e-4 in the
 * blended corner regions, 0.1° outside them; tests/gpu/acc/acc.gpu.test.ts: 2e-6, 0.02°), so 1.2e-4 of
 * the diagonal and 0.12° (angles compared outside the GPU evaluator's blended corner regions, where
 * its normal has no stated bound). On the regular torus both are 0 to f32.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { CCReference, randomSamples } from '../../support/cc-checks.ts';
import { ExactAt, bboxDiagonal, boundaryCages } from '../../support/acc-checks.ts';
import { angleBetween } from '../../support/tess-checks.ts';
import { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import { AccPatches, accFaceParam } from '../../../src/gpu/acc/patches.ts';
import { AccErrorView } from '../../../src/gpu/acc/error.ts';
import { ACC_SCHEMES } from '../../../src/subdiv/acc.ts';
import { AccSurface } from '../../../src/subdiv/acc-evaluate.ts';
import { type Cage, loadCage } from '../../../src/mesh/index.ts';
import creature from '../../../public/models/creature.obj?raw';
import torus from '../../../public/models/torus.obj?raw';

const POSITION_TOL = 1.2e-4; // × bbox diagonal
const ANGLE_TOL_DEG = 0.12;

let tess: Tessellator | undefined;
afterAll(() => {
  tess?.destroy();
  return releaseDevice();
});

const models: [string, () => Cage][] = [
  ['torus', () => loadCage(torus).cage],
  ['creature', () => loadCage(creature).cage],
  ['open prism 5, sharp loop and corner', () => boundaryCages()[0][1]],
];

describe('ACC error view: distance and normal angle to the exact surface on the GPU', () => {
  for (const [name, make] of models) {
    it(`${name}: every scheme, element by element against the CPU`, async () => {
      const device = await getDevice();
      tess ??= Tessellator.create(device, bakeTables(64), { surface: 'catmull-clark', flatBaseline: false });
      const cage = make();
      const mesh = prepareMesh(cage);
      const ccData = buildCatmullClark(cage, mesh);
      const ccRef = new CCReference(cage, mesh, ccData);
      tess.setMesh(mesh, ccData);
      const enc = device.createCommandEncoder();
      tess.encode(enc, testCamera(mesh, 1.5 * mesh.size, undefined, 4));
      device.queue.submit([enc.finish()]);
      const diag = bboxDiagonal(cage.positions);
      const exact = new ExactAt(cage);
      const points = randomSamples(mesh, 600, 5);
      const params = points.map((p) => accFaceParam(mesh, cage, p.t, [(65536 - p.w1 - p.w2) / 65536, p.w1 / 65536, p.w2 / 65536]));
      const refs = params.map(([f, u, v]) => exact.at(f, u, v));
      const blended = points.map((p) => ccRef.at(p.t, [(65536 - p.w1 - p.w2) / 65536, p.w1 / 65536, p.w2 / 65536]).blended);
      for (const scheme of ACC_SCHEMES) {
        device.pushErrorScope('validation');
        const acc = new AccPatches(device, cage, scheme);
        const e2 = device.createCommandEncoder();
        acc.encode(e2, tess.cageBuffer);
        device.queue.submit([e2.finish()]);
        const view = new AccErrorView(device, acc, mesh, cage);
        const gpu = await view.measure(tess, points);
        expect((await device.popErrorScope())?.message).toBeUndefined();
        const cpu = new AccSurface(cage, scheme);
        let dP = 0,
          dN = 0,
          maxErr = 0;
        params.forEach(([f, u, v], i) => {
          const a = cpu.evaluate(f, u, v),
            r = refs[i];
          expect(Number.isFinite(gpu.dist[i]) && Number.isFinite(gpu.angleDeg[i]), `NaN at ${i}`).toBe(true);
          const d = Math.hypot(a.P[0] - r.P[0], a.P[1] - r.P[1], a.P[2] - r.P[2]);
          maxErr = Math.max(maxErr, d / diag);
          dP = Math.max(dP, Math.abs(gpu.dist[i] - d) / diag);
          if (r.normalDefined && !blended[i] && a.N.some((x) => x !== 0))
            dN = Math.max(dN, Math.abs(gpu.angleDeg[i] - (angleBetween(a.N, r.N) * 180) / Math.PI));
        });
        console.log(
          `${name} ${scheme}: max error ${maxErr.toExponential(2)}; GPU − CPU: distance ${dP.toExponential(2)}, angle ${dN.toExponential(2)}°`,
        );
        expect(dP).toBeLessThan(POSITION_TOL);
        expect(dN).toBeLessThan(ANGLE_TOL_DEG);
        view.destroy();
        acc.destroy();
      }
    });
  }
});
