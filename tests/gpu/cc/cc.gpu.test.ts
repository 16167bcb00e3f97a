/**
 * The Catmull-Clark surface on a real WebGPU adapter (Dawn in Node, headless Chromium; both
 * SwiftShader in CI), held against the exact CPU reference (src/subdiv) on every project model:
 * random (triangle, barycentric) samples and every output vertex of a tessellation; watertight,
 * no NaN; an animated cage re-running only the patch build; the flat-baseline pop test.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { checkTessellation } from '../../support/tess-checks.ts';
import { CCReference, randomSamples } from '../../support/cc-checks.ts';
import { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { readBuffer, readMesh, type MeshReadback } from '../../../src/gpu/device/readback.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { sampleSurface } from '../../../src/gpu/tess/sample-surface.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import { decodeBary } from '../../../src/gpu/contract/tess.ts';
import { loadCage } from '../../../src/mesh/index.ts';
import creasedBox from '../../../public/models/creased-box.obj?raw';
import creature from '../../../public/models/creature.obj?raw';
import gear from '../../../public/models/gear.obj?raw';
import icosphere from '../../../public/models/icosphere.obj?raw';
import pawn from '../../../public/models/pawn.obj?raw';
import sheet from '../../../public/models/sheet.obj?raw';
import torus from '../../../public/models/torus.obj?raw';
import { countingEncoder } from '../../support/count-dispatches.ts';

const tables = bakeTables(64);
let tess: Tessellator | undefined;
afterAll(() => {
  tess?.destroy();
  return releaseDevice();
});

/** Bounds (fractions of the bounding-box diagonal, degrees) stated by the issue and by us. */
const POSITION_BOUND = 1e-5;
const NORMAL_BOUND_DEG = 0.1;
const BLENDED_POSITION_BOUND = 1e-4;

const camera = testCamera;

/** Dispatches of one rebuild on the Catmull-Clark surface: 53 (torus) to 60 (creased box) when
 * first counted; since, the tessellator's chain of 7 (tests/gpu/tess/tessellator.gpu.test.ts)
 * after the patch build's one per refinement level, the slices where there are extraordinary
 * vertices, and the limits. The throughput work's bound is 12, which a cage of up to three levels
 * meets: extraordinary vertices, triangles, n-gons (the talk's models: two) and semi-sharp creases
 * that are not single creases (the creased box: three). */
const CC_DISPATCHES_BOUND = 12;
const ccDispatches = (cc: { levelRanges: unknown[]; sliceWorkgroups: number }) =>
  7 + cc.levelRanges.length + (cc.sliceWorkgroups ? 1 : 0) + 1;

async function tessellator(): Promise<Tessellator> {
  const device = await getDevice();
  tess ??= Tessellator.create(device, tables, {
    vertexCapacity: 1 << 20,
    triangleCapacity: 1 << 20,
    surface: 'catmull-clark',
    flatBaseline: false,
  });
  return tess;
}

function outputItems(out: MeshReadback) {
  const items: { t: number; w: [number, number, number] }[] = [];
  for (let v = 0; v < out.vertexCount; v++) {
    const b = out.bary[v];
    const [, w1, w2] = decodeBary(b);
    items.push({ t: out.srcTri[v], w: [(65536 - w1 - w2) / 65536, w1 / 65536, w2 / 65536] });
  }
  return items;
}

const models: [string, string, boolean][] = [
  ['torus', torus, true],
  ['creased-box', creasedBox, true],
  ['sheet', sheet, false],
  ['pawn', pawn, true],
  ['creature', creature, true],
  ['icosphere', icosphere, true],
  ['gear', gear, true],
  // Its rims infinitely sharp: crease vertices whose sector on the cap is one face (θ = π), whose
  // normal is the face's along its diagonal on both sides (src/subdiv/limit.ts K1_LEVELS).
  ['gear, rims infinitely sharp', gear.replace(/^(t crease 2\/1\/0 \d+ \d+) 2$/gm, '$1 10'), true],
];

describe('Catmull-Clark surface against the CPU reference', () => {
  for (const [name, text, closed] of models) {
    it(`${name}: samples and tessellation match the exact limit; watertight; no NaN`, async () => {
      const t = await tessellator();
      const device = t.device;
      const cage = loadCage(text).cage;
      const mesh = prepareMesh(cage);
      const cc = buildCatmullClark(cage, mesh);
      const ref = new CCReference(cage, mesh, cc);
      device.pushErrorScope('validation');
      t.setMesh(mesh, cc);
      const { encoder: enc, counts } = countingEncoder(device.createCommandEncoder());
      t.encode(enc, camera(mesh, 1.5 * mesh.size, undefined, 4));
      device.queue.submit([enc.finish()]);
      expect(counts.direct + counts.indirect, `${name}: ${JSON.stringify(counts)}`).toBe(ccDispatches(cc));
      if (cc.levelRanges.length <= 3) expect(counts.direct + counts.indirect, name).toBeLessThanOrEqual(CC_DISPATCHES_BOUND);
      const out = await readMesh(device, t.output);
      const edgeF = new Uint32Array(await readBuffer(device, t.workBuffer, 4 * mesh.edgeCount, 4 * t.workLayout.edgeF));
      const samples = randomSamples(mesh, 2000);
      const gpu = await sampleSurface(t, samples);
      expect((await device.popErrorScope())?.message).toBeUndefined();

      const s = ref.compare(samples, gpu.pos, gpu.normal);
      const o = ref.compare(outputItems(out), out.positions, out.normals);
      console.log(
        name,
        JSON.stringify({
          dispatches: counts.direct + counts.indirect,
          samples: s,
          output: o,
          vertices: out.vertexCount,
          triangles: out.triangleCount,
        }),
      );
      for (const r of [s, o]) {
        expect(r.nan).toBe(0);
        expect(r.exact.maxP, r.exact.worst).toBeLessThan(POSITION_BOUND);
        expect(r.exact.maxN).toBeLessThan(NORMAL_BOUND_DEG);
        expect(r.blended.maxP, r.blended.worst).toBeLessThan(BLENDED_POSITION_BOUND);
      }
      const report = checkTessellation(mesh, edgeF, out, {
        closed,
        split: true,
        // The blended squares round irregular vertices are held to their own bound, as above.
        reference: (tri, w) => {
          const { ref: r, blended } = ref.at(tri, w);
          return { pos: r.P, normal: r.N, bound: blended ? BLENDED_POSITION_BOUND : POSITION_BOUND };
        },
      });
      expect(report.problems).toEqual([]);
    });
  }
});
