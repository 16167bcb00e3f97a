/**
 * The compute tessellator on a real WebGPU adapter (Dawn in Node, or headless Chromium; both on
 * SwiftShader in CI), held against the CPU: patterns bit for bit, counts, Phong surface within
 * 1e-5 of the model size, watertight after the weld, no NaN, the budget respected.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { mat4 } from 'gl-matrix';
import { getDevice, releaseDevice } from './gpu-device.ts';
import { checkTessellation } from './tess-checks.ts';
import { cube, octahedron, torus, sheet } from './cages/shapes.ts';
import { Tessellator } from '../src/gpu/tessellator.ts';
import { prepareMesh, type PreparedMesh } from '../src/gpu/prepare.ts';
import { readBuffer, readMesh } from '../src/gpu/readback.ts';
import { bakeTables } from '../src/pattern/tables.ts';
import type { FactorParams } from '../src/gpu/types.ts';
import type { Cage } from '../src/mesh/types.ts';

const tables = bakeTables(64);
afterAll(() => releaseDevice());


function camera(mesh: PreparedMesh, eyeDistance: number, fixed?: number, lodScale = 1): FactorParams {
  const c = [0, 1, 2].map((i) => (mesh.bboxMin[i] + mesh.bboxMax[i]) / 2) as [number, number, number];
  const eye: [number, number, number] = [c[0] + 0.3 * eyeDistance, c[1] + 0.5 * eyeDistance, c[2] + eyeDistance];
  const view = mat4.lookAt(mat4.create(), eye, c, [0, 1, 0]);
  const proj = mat4.perspectiveZO(mat4.create(), Math.PI / 4, 1, 0.01, 100);
  const viewProj = mat4.multiply(mat4.create(), proj, view) as Float32Array;
  return { mode: fixed ? 'fixed' : 'adaptive', fixedFactor: fixed ?? 1, lodScale, viewProj, eye, viewportHeight: 720, fovY: Math.PI / 4 };
}

// Pipelines compile once per capacity setting (SwiftShader compiles slowly).
const tessellators = new Map<string, Tessellator>();
afterAll(() => tessellators.forEach((t) => t.destroy()));

async function tessellate(cage: Cage, params: (m: PreparedMesh) => FactorParams, opts: { vertexCapacity?: number; triangleCapacity?: number } = {}) {
  const device = await getDevice();
  const mesh = prepareMesh(cage);
  device.pushErrorScope('validation');
  const key = JSON.stringify(opts);
  let tess = tessellators.get(key);
  if (!tess) tessellators.set(key, (tess = Tessellator.create(device, tables, { vertexCapacity: 1 << 20, triangleCapacity: 1 << 20, ...opts })));
  tess.setMesh(mesh);
  const enc = device.createCommandEncoder({ label: 'test rebuild' });
  tess.encode(enc, params(mesh));
  device.queue.submit([enc.finish()]);
  const out = await readMesh(device, tess.output);
  const edgeF = new Uint32Array(await readBuffer(device, tess.workBuffer, 4 * mesh.edgeCount, 4 * tess.workLayout.edgeF));
  const error = await device.popErrorScope();
  return { mesh, out, edgeF, error };
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
          setting === 'fixed 1' ? camera(m, 4, 1)
          : setting === 'fixed 5.5' ? camera(m, 4, 5.5)
          : setting === 'fixed 16' ? camera(m, 4, 16)
          : setting === 'adaptive near' ? camera(m, 1.5 * m.size, undefined, 4)
          : camera(m, 6 * m.size);
        const { mesh, out, edgeF, error } = await tessellate(make(), params);
        expect(error?.message).toBeUndefined();
        const report = checkTessellation(mesh, edgeF, out, { closed });
        expect(report.problems).toEqual([]);
        expect(out.attempt).toBe(0);
        if (setting === 'fixed 16') expect(out.triangleCount).toBe(256 * mesh.triangleCount);
        expect(report.maxNormalError).toBeLessThan(1e-4);
      });
    }
  }

  it('adaptive factors rise near the eye and fall away from it', async () => {
    const near = await tessellate(torus(), (m) => camera(m, 1.2 * m.size, undefined, 2));
    const far = await tessellate(torus(), (m) => camera(m, 8 * m.size, undefined, 2));
    expect(near.out.triangleCount).toBeGreaterThan(far.out.triangleCount);
  });

  it('respects a deliberately tiny budget without error, still watertight', async () => {
    const cage = torus();
    const nT = prepareMesh(cage).triangleCount;
    const { mesh, out, edgeF, error } = await tessellate(cage, (m) => camera(m, 4, 64), { vertexCapacity: 600, triangleCapacity: 4 * nT });
    expect(error?.message).toBeUndefined();
    expect(out.attempt).toBeGreaterThan(0);
    expect(out.triangleCount).toBeLessThanOrEqual(4 * nT);
    expect(out.vertexCount).toBeLessThanOrEqual(600);
    expect(checkTessellation(mesh, edgeF, out, { closed: true }).problems).toEqual([]);
  });
});
