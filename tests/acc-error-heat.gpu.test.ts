/**
 * The demo's ACC error views on the GPU (src/gpu/acc-heat.ts, wgsl/acc-heat.wgsl): after an ACC
 * tessellator's rebuild, the pass over its output vertices. Each vertex's value is held, element
 * by element, against the f64 CPU references at the vertex's own cage parameter (srcTri, bary →
 * accFaceParam; src/subdiv/acc.ts AccSurface against the exact evaluator), with the tolerances
 * of tests/acc-error.gpu.test.ts (1.2e-4 of the diagonal; 0.12° outside the exact GPU evaluator's
 * blended corner regions); vertices of regular patches are exactly 0 (the pass skips them: the
 * schemes are exact there); the totals read back are the max and RMS of those values (f32 sums:
 * 1e-4 relative). The regular torus gives 0 everywhere.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { getDevice, releaseDevice, testCamera } from './gpu-device.ts';
import { CCReference } from './cc-checks.ts';
import { ExactAt } from './acc-checks.ts';
import { angleBetween } from './tess-checks.ts';
import { Tessellator } from '../src/gpu/tessellator.ts';
import { prepareMesh } from '../src/gpu/prepare.ts';
import { buildCatmullClark } from '../src/gpu/cc/build.ts';
import { bakeTables } from '../src/pattern/tables.ts';
import { accFaceParam } from '../src/gpu/acc.ts';
import { prepareAccSurface } from '../src/gpu/acc-surface.ts';
import { AccHeatPass, cageDiagonal } from '../src/gpu/acc-heat.ts';
import { readBuffer, readMesh } from '../src/gpu/readback.ts';
import { AccSurface, KIND_REGULAR, type AccScheme } from '../src/subdiv/acc.ts';
import { decodeBary } from '../src/gpu/contract.ts';
import { loadCage } from '../src/mesh/index.ts';
import creature from '../public/models/creature.obj?raw';
import torus from '../public/models/torus.obj?raw';

const POSITION_TOL = 1.2e-4; // × bbox diagonal
const ANGLE_TOL_DEG = 0.12;

const tables = bakeTables(64);
const made: { destroy(): void }[] = [];
afterAll(() => {
  made.forEach((t) => t.destroy());
  return releaseDevice();
});

const cases: [string, string, AccScheme, number][] = [
  ['creature', creature, 'gregory-acc', 3],
  ['creature', creature, 'bezier-acc', 2],
  ['torus', torus, 'pm-acc', 3],
];

describe('ACC error views: per output vertex on the GPU', () => {
  for (const [name, text, scheme, factor] of cases) {
    it(`${name} ${scheme}: every vertex against the CPU, totals are its max and RMS`, async () => {
      const device = await getDevice();
      const cage = loadCage(text).cage;
      const mesh = prepareMesh(cage);
      const ccData = buildCatmullClark(cage, mesh);
      const camera = testCamera(mesh, 1.5 * mesh.size, factor);
      device.pushErrorScope('validation');
      const reference = Tessellator.create(device, tables, {
        surface: 'catmull-clark',
        flatBaseline: false,
        vertexCapacity: 1 << 14,
        triangleCapacity: 1 << 14,
      });
      const tess = Tessellator.create(device, tables, { surface: scheme, vertexCapacity: 1 << 16, triangleCapacity: 1 << 16 });
      const acc = prepareAccSurface(device, cage, mesh, scheme);
      made.push(reference, tess, acc.patches);
      reference.setMesh(mesh, ccData);
      tess.setMesh(mesh, undefined, acc);
      const heat = new AccHeatPass(device, acc.patches, mesh, cage, tess.output.vertexCapacity);
      made.push(heat);
      const enc = device.createCommandEncoder();
      reference.encode(enc, { ...camera, fixedFactor: 1 });
      tess.encode(enc, camera);
      heat.encode(enc, reference, tess.output);
      device.queue.submit([enc.finish()]);
      const totals = await heat.read();
      const out = await readMesh(device, tess.output);
      const v = heat.values;
      const values = new Float32Array(await readBuffer(device, v.buffer, 8 * out.vertexCount, v.offset));
      expect((await device.popErrorScope())?.message).toBeUndefined();

      const diag = cageDiagonal(cage.positions);
      const cpu = new AccSurface(cage, scheme);
      const exact = new ExactAt(cage);
      const ccRef = new CCReference(cage, mesh, ccData);
      const kinds = acc.patches.topology.patches;
      let dP = 0,
        dN = 0,
        max = [0, 0],
        sum = [0, 0],
        n = 0,
        regular = 0;
      for (let i = 0; i < out.vertexCount; i++) {
        const t = out.srcTri[i];
        if (t === 0xffffffff) continue;
        n++;
        const gd = values[2 * i],
          ga = values[2 * i + 1];
        expect(Number.isFinite(gd) && Number.isFinite(ga), `NaN at ${i}`).toBe(true);
        max = [Math.max(max[0], gd), Math.max(max[1], ga)];
        sum = [sum[0] + gd * gd, sum[1] + ga * ga];
        const w = decodeBary(out.bary[i]).map((x) => x / 65536) as [number, number, number];
        const [f, u, vv] = accFaceParam(mesh, cage, t, w);
        if (kinds[2 * f] === KIND_REGULAR) {
          regular++;
          expect(gd).toBe(0);
          expect(ga).toBe(0);
          continue;
        }
        const a = cpu.evaluate(f, u, vv),
          r = exact.at(f, u, vv);
        const d = Math.hypot(a.P[0] - r.P[0], a.P[1] - r.P[1], a.P[2] - r.P[2]) / diag;
        dP = Math.max(dP, Math.abs(gd - d));
        if (r.normalDefined && !ccRef.at(t, w).blended && a.N.some((x) => x !== 0))
          dN = Math.max(dN, Math.abs(ga - (angleBetween(a.N, r.N) * 180) / Math.PI));
      }
      console.log(
        `${name} ${scheme} factor ${factor}: ${out.vertexCount} vertices (${regular} on regular patches); max ${(100 * max[0]).toFixed(4)}% ${max[1].toFixed(3)}°; GPU − CPU ${dP.toExponential(2)}, ${dN.toExponential(2)}°`,
      );
      expect(n).toBeGreaterThan(0);
      expect(dP).toBeLessThan(POSITION_TOL);
      expect(dN).toBeLessThan(ANGLE_TOL_DEG);
      expect(totals).not.toBeNull();
      expect(totals!.vertices).toBe(n);
      expect(totals!.maxDistance).toBe(Math.fround(max[0]));
      expect(totals!.maxAngle).toBe(Math.fround(max[1]));
      expect(Math.abs(totals!.rmsDistance - Math.sqrt(sum[0] / n))).toBeLessThanOrEqual(1e-4 * Math.sqrt(sum[0] / n));
      expect(Math.abs(totals!.rmsAngle - Math.sqrt(sum[1] / n))).toBeLessThanOrEqual(1e-4 * Math.sqrt(sum[1] / n));
      if (name === 'torus') {
        expect(regular).toBe(n);
        expect(totals!.maxDistance).toBe(0);
        expect(totals!.maxAngle).toBe(0);
      } else {
        expect(totals!.maxDistance).toBeGreaterThan(0);
      }
    });
  }
});
