/**
 * The compute tessellator on a real WebGPU adapter (Dawn in Node, or headless Chromium; both on
 * SwiftShader in CI), held against the CPU: patterns bit for bit, counts, Phong surface within
 * 1e-5 of the model size, watertight after the weld, no NaN, the budget respected.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { checkTessellation } from '../../support/tess-checks.ts';
import { cube, octahedron, torus, sheet } from '../../support/shapes.ts';
import { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { createTessPipelines } from '../../../src/gpu/tess/pipelines.ts';
import { prepareMesh, type PreparedMesh } from '../../../src/gpu/tess/prepare.ts';
import { readBuffer, readMesh } from '../../../src/gpu/device/readback.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import type { FactorParams } from '../../../src/gpu/contract/tessellated-mesh.ts';
import type { Cage } from '../../../src/mesh/types.ts';
import { countingEncoder } from '../../support/count-dispatches.ts';
import { BUDGET_CANDIDATES, BUDGET_SCALES } from '../../../src/gpu/contract/tess.ts';
import { budgetCandidate } from '../../../src/gpu/tess/factors.ts';
import { MAX_FACTOR } from '../../../src/pattern/max-factor.ts';

const tables = bakeTables(64);
afterAll(() => releaseDevice());

const camera = testCamera;

/** Dispatches of one Phong rebuild: 51 when the counting test was written (three budget attempts
 * recorded whatever the first decided, three scan steps per prefix sum, the weld in two
 * dispatches), 8 since the count pass computes the edges' factors and counts every budget
 * candidate scale (contract/tess.ts BUDGET_SCALES) and emit writes the welded vertices with the
 * rest, 7 since each workgroup of the scan's down-sweep makes the budget's choice from the block
 * sums itself (wgsl/tess/scan.wgsl). The throughput work's bound is 12; it may only fall. */
const PHONG_DISPATCHES = 7;

// Pipelines compile once per capacity setting (SwiftShader compiles slowly).
const tessellators = new Map<string, Tessellator>();
afterAll(() => tessellators.forEach((t) => t.destroy()));

async function tessellate(
  cage: Cage,
  params: (m: PreparedMesh) => FactorParams,
  opts: { vertexCapacity?: number; triangleCapacity?: number } = {},
) {
  const device = await getDevice();
  const mesh = prepareMesh(cage);
  device.pushErrorScope('validation');
  const key = JSON.stringify(opts);
  let tess = tessellators.get(key);
  if (!tess)
    tessellators.set(key, (tess = Tessellator.create(device, tables, { vertexCapacity: 1 << 20, triangleCapacity: 1 << 20, ...opts })));
  tess.setMesh(mesh);
  const enc = device.createCommandEncoder({ label: 'test rebuild' });
  tess.encode(enc, params(mesh));
  device.queue.submit([enc.finish()]);
  const out = await readMesh(device, tess.output);
  const edgeF = new Uint32Array(await readBuffer(device, tess.workBuffer, 4 * mesh.edgeCount, 4 * tess.workLayout.edgeF));
  const error = await device.popErrorScope();
  return { mesh, out, edgeF, error };
}

/** Each budget candidate's output vertices and triangles, from the counts the GPU made at every
 * candidate (TESS_WORK's lanes): what the budget pass chose among. */
async function candidateTotals(mesh: PreparedMesh, opts: object) {
  const device = await getDevice();
  const tess = tessellators.get(JSON.stringify(opts))!;
  const lanes = async (name: 'edgeInterior' | 'triVertCount' | 'triTriCount', n: number) =>
    new Uint32Array(await readBuffer(device, tess.workBuffer, 4 * n * BUDGET_CANDIDATES, 4 * tess.workLayout[name]));
  const [edge, vert, tri] = await Promise.all([
    lanes('edgeInterior', mesh.edgeCount),
    lanes('triVertCount', mesh.triangleCount),
    lanes('triTriCount', mesh.triangleCount),
  ]);
  const sum = (a: Uint32Array, c: number, n: number) => a.subarray(c * n, (c + 1) * n).reduce((x, y) => x + y, 0);
  return BUDGET_SCALES.map((_, c) => ({
    vertices: mesh.vertexCount + sum(edge, c, mesh.edgeCount) + sum(vert, c, mesh.triangleCount),
    triangles: sum(tri, c, mesh.triangleCount),
  }));
}

const shapes: [string, () => Cage, boolean][] = [
  ['cube', cube, true],
  ['octahedron', octahedron, true],
  ['torus', () => torus(), true],
  ['open sheet', sheet, false],
];

describe('compute tessellator', () => {
  for (const [name, make, closed] of shapes) {
    for (const setting of ['fixed 1', 'fixed 5.5', 'fixed 16', 'adaptive near', 'adaptive far'] as const) {
      it(`${name}, ${setting}: matches the CPU and is watertight`, async () => {
        const params = (m: PreparedMesh) =>
          setting === 'fixed 1'
            ? camera(m, 4, 1)
            : setting === 'fixed 5.5'
              ? camera(m, 4, 5.5)
              : setting === 'fixed 16'
                ? camera(m, 4, 16)
                : setting === 'adaptive near'
                  ? camera(m, 1.5 * m.size, undefined, 4)
                  : camera(m, 6 * m.size);
        const { mesh, out, edgeF, error } = await tessellate(make(), params);
        expect(error?.message).toBeUndefined();
        const report = checkTessellation(mesh, edgeF, out, { closed });
        expect(report.problems).toEqual([]);
        expect(out.budgetCandidate).toBe(0);
        if (setting === 'fixed 16') expect(out.triangleCount).toBe(256 * mesh.triangleCount);
        expect(report.maxNormalError).toBeLessThan(1e-4);
      });
    }
  }

  it('a tessellator handed a set of pipelines made before (as the demo keeps them) builds what one that makes its own builds, bit for bit', async () => {
    const device = await getDevice();
    const pipelines = createTessPipelines(device, 'phong');
    const cage = torus();
    const { out: once } = await tessellate(cage, (m) => camera(m, 1.5 * m.size, undefined, 4));
    const tess = Tessellator.create(device, tables, { vertexCapacity: 1 << 20, triangleCapacity: 1 << 20, pipelines });
    const mesh = prepareMesh(cage);
    tess.setMesh(mesh);
    const enc = device.createCommandEncoder({ label: 'rebuild with pipelines made before' });
    tess.encode(enc, camera(mesh, 1.5 * mesh.size, undefined, 4));
    device.queue.submit([enc.finish()]);
    const made = await readMesh(device, tess.output);
    tess.destroy();
    expect(made.triangleCount).toBe(once.triangleCount);
    expect(made.positions).toEqual(once.positions);
    expect(made.indices).toEqual(once.indices);
    // A set is for its own surface only.
    expect(() => Tessellator.create(device, tables, { surface: 'catmull-clark', pipelines })).toThrow(/pipelines for phong/);
  });

  it("a rebuild's dispatch chain on the Phong surface: counted, whatever the size and the budget", async () => {
    // Each dispatch is a launch and a barrier on a GPU, so a short chain is a floor on the
    // rebuild's time whatever the size: the bulge, factors + count, the scan's two steps (the
    // budget chosen in the second), plan, and emit's vertices (the welded ones too) and triangles.
    const device = await getDevice();
    for (const [cage, opts] of [
      [cube(), {}],
      [torus(90, 48), {}], // several scan blocks
      [torus(), { vertexCapacity: 600, triangleCapacity: 4 * prepareMesh(torus()).triangleCount }], // over budget
    ] as const) {
      await tessellate(cage, (m) => camera(m, 4, 16), opts);
      const tess = tessellators.get(JSON.stringify(opts))!;
      const { encoder, counts } = countingEncoder(device.createCommandEncoder({ label: 'counted rebuild' }));
      tess.encode(encoder, camera(prepareMesh(cage), 4, 16));
      device.queue.submit([encoder.finish()]);
      console.log(`Phong rebuild: ${counts.passes} compute passes, ${counts.direct} + ${counts.indirect} indirect dispatches`);
      expect(counts.indirect).toBe(1); // the vertices' emit (the triangles' is a workgroup per cage triangle)
      expect(counts.direct + counts.indirect).toBe(PHONG_DISPATCHES);
    }
  });

  it(`at the top factor (MAX_FACTOR, ${MAX_FACTOR}) and between 64 and it: matches the CPU and is watertight`, async () => {
    // The talk's counts need 128 (suzanne: 968 triangles at 128²); the other tests bake to 64.
    const device = await getDevice();
    const top = Tessellator.create(device, bakeTables(MAX_FACTOR), { vertexCapacity: 1 << 20, triangleCapacity: 1 << 20 });
    try {
      for (const f of [MAX_FACTOR, 100.5]) {
        const mesh = prepareMesh(cube());
        device.pushErrorScope('validation');
        top.setMesh(mesh);
        const enc = device.createCommandEncoder({ label: 'test rebuild at the top factor' });
        top.encode(enc, camera(mesh, 4, f));
        device.queue.submit([enc.finish()]);
        const out = await readMesh(device, top.output);
        const edgeF = new Uint32Array(await readBuffer(device, top.workBuffer, 4 * mesh.edgeCount, 4 * top.workLayout.edgeF));
        expect((await device.popErrorScope())?.message).toBeUndefined();
        expect(out.budgetCandidate).toBe(0);
        if (f === MAX_FACTOR) expect(out.triangleCount).toBe(MAX_FACTOR * MAX_FACTOR * mesh.triangleCount);
        expect(checkTessellation(mesh, edgeF, out, { closed: true }).problems).toEqual([]);
      }
    } finally {
      top.destroy();
    }
  });

  it('a cage of more triangles than one scan block covers (4096) matches the CPU', async () => {
    const big = torus(90, 48); // 4320 quads, 8640 triangles, ~13K edges: several scan blocks
    for (const params of [(m: PreparedMesh) => camera(m, 4, 3.5), (m: PreparedMesh) => camera(m, 0.8 * m.size, undefined, 4)]) {
      const { mesh, out, edgeF, error } = await tessellate(big, params);
      expect(mesh.triangleCount).toBeGreaterThan(2 * 4096);
      expect(error?.message).toBeUndefined();
      expect(checkTessellation(mesh, edgeF, out, { closed: true }).problems).toEqual([]);
    }
  });

  it('adaptive factors rise near the eye and fall away from it', async () => {
    const near = await tessellate(torus(), (m) => camera(m, 1.2 * m.size, undefined, 2));
    const far = await tessellate(torus(), (m) => camera(m, 8 * m.size, undefined, 2));
    expect(near.out.triangleCount).toBeGreaterThan(far.out.triangleCount);
  });

  it('respects a deliberately tiny budget without error, still watertight', async () => {
    const cage = torus();
    const nT = prepareMesh(cage).triangleCount;
    const opts = { vertexCapacity: 600, triangleCapacity: 4 * nT };
    const { mesh, out, edgeF, error } = await tessellate(cage, (m) => camera(m, 4, 64), opts);
    expect(error?.message).toBeUndefined();
    expect(out.budgetCandidate).toBeGreaterThan(0);
    expect(out.triangleCount).toBeLessThanOrEqual(4 * nT);
    expect(out.vertexCount).toBeLessThanOrEqual(600);
    expect(checkTessellation(mesh, edgeF, out, { closed: true }).problems).toEqual([]);
    // The GPU's choice is the CPU twin's over the counts the GPU made at every candidate.
    expect({ candidate: out.budgetCandidate, fits: true }).toEqual(budgetCandidate(await candidateTotals(mesh, opts), 600, 4 * nT));
    expect(out.scale).toBe(Math.fround(BUDGET_SCALES[out.budgetCandidate]));
  });
});

// The project's own models, at several cameras and settings.
import creasedBox from '../../../public/models/creased-box.obj?raw';
import creature from '../../../public/models/creature.obj?raw';
import gear from '../../../public/models/gear.obj?raw';
import icosphere from '../../../public/models/icosphere.obj?raw';
import pawn from '../../../public/models/pawn.obj?raw';
import sheetModel from '../../../public/models/sheet.obj?raw';
import torusModel from '../../../public/models/torus.obj?raw';
import { loadCage } from '../../../src/mesh/index.ts';
import { adaptiveRuleOf } from '../../../src/gpu/tess/factors.ts';
import { phongEdgeBulges, phongEdgeFactors } from '../../../src/gpu/surface/phong.ts';
import { ONE } from '../../../src/pattern/fixed.ts';

const models: [string, string, boolean][] = [
  ['creased-box', creasedBox, true],
  ['creature', creature, true],
  ['gear', gear, true],
  ['icosphere', icosphere, true],
  ['pawn', pawn, true],
  ['sheet', sheetModel, false],
  ['torus', torusModel, true],
];

describe('compute tessellator on the project models', () => {
  for (const [name, text, closed] of models) {
    it(`${name}: fixed 7.3, adaptive near and far match the CPU and are watertight`, async () => {
      const cage = loadCage(text).cage;
      for (const params of [
        (m: PreparedMesh) => camera(m, 4, 7.3),
        (m: PreparedMesh) => camera(m, 0.9 * m.size, undefined, 8),
        (m: PreparedMesh) => camera(m, 3 * m.size, undefined, 2),
      ]) {
        const { mesh, out, edgeF, error } = await tessellate(cage, params);
        expect(error?.message).toBeUndefined();
        const report = checkTessellation(mesh, edgeF, out, { closed });
        expect(report.problems).toEqual([]);
        expect(report.maxNormalError).toBeLessThan(1e-4);
      }
    });
  }

  it('computes the adaptive factor rule of src/gpu/tess/factors.ts', async () => {
    const cage = loadCage(creature).cage;
    const p = (m: PreparedMesh) => camera(m, 1.2 * m.size, undefined, 3);
    const { mesh, edgeF } = await tessellate(cage, p);
    const fp = p(mesh);
    const rule = adaptiveRuleOf(fp);
    // The bulge term of each edge's two triangles, on the same (Phong) surface.
    const bulge = phongEdgeBulges(mesh, rule);
    expect(bulge.some((k) => k > 1)).toBe(true);
    const factors = phongEdgeFactors(mesh, rule);
    let compared = 0;
    for (let e = 0; e < mesh.edgeCount; e++) {
      const cpu = factors[e];
      const gpu = edgeF[e] / ONE;
      // f32 against f64: the same within 1e-4 relative, except where a culling test sits on its threshold.
      if (Math.abs(gpu - cpu) > 1e-4 * cpu && (gpu === 1 || cpu === 1)) continue;
      expect(Math.abs(gpu - cpu)).toBeLessThanOrEqual(1e-4 * cpu + 2 / ONE);
      compared++;
    }
    expect(compared).toBeGreaterThan(0.95 * mesh.edgeCount);
  });
});
