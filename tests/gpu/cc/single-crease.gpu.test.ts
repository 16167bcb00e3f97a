/**
 * Single-crease patches on a real WebGPU adapter: a cage whose creases (σ = 2.7 and 0.5) run
 * straight through valence-4 vertices is prepared without the ceil(σ) uniform levels, and the
 * GPU surface (crease row weights × cubic B-spline, wgsl/cc/surface.wgsl) and the vertex limits
 * (wgsl/cc/build.wgsl vertexLimit) match the exact CPU reference within tests/gpu/cc/cc.gpu.test.ts bounds.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { checkTessellation, angleBetween } from '../../support/tess-checks.ts';
import { CCReference, exactTessellator, randomSamples } from '../../support/cc-checks.ts';
import type { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { readBuffer, readMesh } from '../../../src/gpu/device/readback.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { sampleSurface } from '../../../src/gpu/tess/sample-surface.ts';
import { decodeBary } from '../../../src/gpu/contract/tess.ts';
import { cornerLimit, creasedGridCube } from '../../support/single-crease-fixture.ts';

const POSITION_BOUND = 1e-5;
const NORMAL_BOUND_DEG = 0.1;
const BLENDED_POSITION_BOUND = 1e-4;

let tess: Tessellator | undefined;
afterAll(() => {
  tess?.destroy();
  return releaseDevice();
});

describe('single-crease patches on the GPU', () => {
  it('cube of 6×6 grids, crease loops σ = 2.7 and 0.5: one level only; surface and vertex limits exact', async () => {
    const device = await getDevice();
    tess ??= exactTessellator(device);
    const t = tess;
    const cage = creasedGridCube(6, [
      [2, 2.7],
      [4, 0.5],
    ]);
    const mesh = prepareMesh(cage);
    const cc = buildCatmullClark(cage, mesh);
    expect(cc.levels).toBe(1);
    expect(cc.singleCreaseCount).toBe(96);
    const ref = new CCReference(cage, mesh, cc);
    device.pushErrorScope('validation');
    t.setMesh(mesh, cc);
    const enc = device.createCommandEncoder();
    t.encode(enc, testCamera(mesh, 1.5 * mesh.size, undefined, 4));
    device.queue.submit([enc.finish()]);
    const out = await readMesh(device, t.output);
    const edgeF = new Uint32Array(await readBuffer(device, t.workBuffer, 4 * mesh.edgeCount, 4 * t.workLayout.edgeF));
    const samples = randomSamples(mesh, 3000);
    const gpu = await sampleSurface(t, samples);
    const nV = mesh.vertexCount;
    // The limit positions, then the limit normals, 3 floats per vertex each (contract/tess.ts TESS_CAGE).
    expect(t.cageLayout.limitNormals).toBe(t.cageLayout.limitPositions + 3 * nV);
    const limits = new Float32Array(await readBuffer(device, t.cageBuffer, 4 * 6 * nV, 4 * t.cageLayout.limitPositions));
    expect((await device.popErrorScope())?.message).toBeUndefined();

    const items = [];
    for (let v = 0; v < out.vertexCount; v++) {
      const b = out.bary[v];
      const [, w1, w2] = decodeBary(b);
      items.push({ t: out.srcTri[v], w: [(65536 - w1 - w2) / 65536, w1 / 65536, w2 / 65536] as [number, number, number] });
    }
    const s = ref.compare(samples, gpu.pos, gpu.normal);
    const o = ref.compare(items, out.positions, out.normals);
    console.log('single-crease cube', JSON.stringify({ samples: s, output: o }));
    for (const r of [s, o]) {
      expect(r.nan).toBe(0);
      expect(r.exact.maxP, r.exact.worst).toBeLessThan(POSITION_BOUND);
      expect(r.exact.maxN, r.exact.worstN).toBeLessThan(NORMAL_BOUND_DEG);
      expect(r.blended.maxP, r.blended.worst).toBeLessThan(BLENDED_POSITION_BOUND);
    }
    const report = checkTessellation(mesh, edgeF, out, {
      closed: true,
      split: true,
      reference: (tri, w) => {
        const r = ref.at(tri, w).ref;
        return { pos: r.P, normal: r.N };
      },
    });
    expect(report.problems).toEqual([]);

    // Vertex limits (the factor rule and the flat baseline read them), crease vertices included.
    let maxP = 0,
      maxN = 0;
    for (let v = 0; v < nV; v++) {
      const r = cornerLimit(ref.S, cage, v);
      const p = [limits[3 * v], limits[3 * v + 1], limits[3 * v + 2]];
      const n = [limits[3 * nV + 3 * v], limits[3 * nV + 3 * v + 1], limits[3 * nV + 3 * v + 2]];
      maxP = Math.max(maxP, Math.hypot(p[0] - r.P[0], p[1] - r.P[1], p[2] - r.P[2]) / mesh.size);
      if (r.normalDefined) maxN = Math.max(maxN, (angleBetween(n, r.N) * 180) / Math.PI);
    }
    console.log('vertex limits', JSON.stringify({ maxP, maxN }));
    expect(maxP).toBeLessThan(POSITION_BOUND);
    expect(maxN).toBeLessThan(NORMAL_BOUND_DEG);
  });
});
