/**
 * ACC patches on a real WebGPU adapter (Dawn in Node, headless Chromium; SwiftShader in CI): the
 * patch build (wgsl/acc/build.wgsl) against the f64 yardstick (src/subdiv/acc.ts) point by point,
 * and the surface (wgsl/acc/surface.wgsl evalAccPatch) at a few hundred random (face, u, v) per
 * scheme, corners, edges and the c-patch diagonal included, on the cube of the reference
 * vectors of tests/gpu/acc/acc.test.ts, an all-triangle octahedron, small project models and cages with boundaries, creases,
 * corners and a cone point. f32 tolerances, relative to the
 * bounding-box diagonal: control points and positions 2e-6; normals 0.02° (measured: ≤ 2e-7 and
 * ≤ 0.003°). No NaN anywhere. A moved cage re-runs only the build and matches again.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { getDevice, releaseDevice } from '../../support/gpu-device.ts';
import { loadCage, type Cage } from '../../../src/mesh/index.ts';
import { ACC_SCHEMES } from '../../../src/subdiv/acc.ts';
import { AccSurface } from '../../../src/subdiv/acc-evaluate.ts';
import { AccPatches } from '../../../src/gpu/acc/patches.ts';
import { bboxDiagonal, boundaryCages, octahedron, randomFaceParams, valence2Cube } from '../../support/acc-checks.ts';
import { angleBetween } from '../../support/tess-checks.ts';
import { cube } from '../../support/subdiv-fixtures.ts';
import creature from '../../../public/models/creature.obj?raw';
import torus from '../../../public/models/torus.obj?raw';
import creasedBox from '../../../public/models/creased-box.obj?raw';
import sheet from '../../../public/models/sheet.obj?raw';

const POSITION_TOL = 2e-6; // × bbox diagonal
const NORMAL_TOL_DEG = 0.02;

afterAll(() => releaseDevice());

function cageBuffer(device: GPUDevice, P: ArrayLike<number>): GPUBuffer {
  const f = Float32Array.from(P);
  const b = device.createBuffer({
    label: 'test cage positions',
    size: f.byteLength,
    usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
  });
  device.queue.writeBuffer(b, 0, f);
  return b;
}

function params(cage: Cage, n: number, seed: number): [number, number, number][] {
  const out = randomFaceParams(cage, n, seed);
  // Corners and edges (where the Gregory blends are 0/0 and the Pm sectors meet).
  out.forEach((p, i) => {
    const tri = cage.faceOffsets[p[0] + 1] - cage.faceOffsets[p[0]] === 3;
    if (i % 10 === 0) {
      p[1] = i % 20 === 0 ? 0 : 1;
      p[2] = tri ? 0 : i % 40 === 0 ? 1 : 0;
    }
    if (i % 10 === 1) p[2] = 0;
    if (i % 10 === 2 && !tri) p[1] = p[2]; // the c-patch diagonal
  });
  return out;
}

const models: [string, () => Cage][] = [
  ['cube', () => cube()],
  ['octahedron', octahedron],
  ['creature', () => loadCage(creature).cage],
  ['torus', () => loadCage(torus).cage],
  // Boundaries, infinitely sharp creases and corners, a cone point, one-face crease sectors.
  ['creased-box', () => loadCage(creasedBox).cage],
  ['sheet', () => loadCage(sheet).cage],
  ['open prism 5, sharp loop and corner', () => boundaryCages()[0][1]],
  ['octahedron, one face dropped', () => boundaryCages()[4][1]],
  ['cube with a valence-2 vertex', () => valence2Cube(cube())],
];

describe('ACC patches on the GPU against the f64 yardstick', () => {
  for (const [name, make] of models) {
    it(`${name}: control points and surface samples of every scheme`, async () => {
      const device = await getDevice();
      const cage = make();
      const diag = bboxDiagonal(cage.positions);
      const cageBuf = cageBuffer(device, cage.positions);
      const pts = params(cage, 300, 11);
      for (const scheme of ACC_SCHEMES) {
        device.pushErrorScope('validation');
        const gpu = new AccPatches(device, cage, scheme);
        const cpu = new AccSurface(cage, scheme);
        const enc = device.createCommandEncoder({ label: 'acc test' });
        gpu.encode(enc, cageBuf);
        device.queue.submit([enc.finish()]);
        const got = await gpu.readPoints();
        let maxPt = 0;
        for (let i = 0; i < got.length; i++) {
          expect(Number.isFinite(got[i])).toBe(true);
          maxPt = Math.max(maxPt, Math.abs(got[i] - cpu.points[i]) / diag);
        }
        expect(maxPt, `${scheme} control points`).toBeLessThan(POSITION_TOL);
        const s = await gpu.sample(pts);
        expect((await device.popErrorScope())?.message).toBeUndefined();
        device.pushErrorScope('validation');
        let maxP = 0,
          maxN = 0,
          worst = '';
        pts.forEach(([f, u, v], i) => {
          const r = cpu.evaluate(f, u, v);
          const p = Array.from(s.pos.subarray(3 * i, 3 * i + 3)),
            n = Array.from(s.normal.subarray(3 * i, 3 * i + 3));
          expect([...p, ...n].every(Number.isFinite), `NaN at ${f} ${u} ${v}`).toBe(true);
          maxP = Math.max(maxP, Math.hypot(p[0] - r.P[0], p[1] - r.P[1], p[2] - r.P[2]) / diag);
          const dn = (angleBetween(n, r.N) * 180) / Math.PI;
          if (dn > maxN) {
            maxN = dn;
            worst = `face ${f} (${u}, ${v}) kind ${cpu.kind(f)}`;
          }
        });
        expect(maxP, `${scheme} positions`).toBeLessThan(POSITION_TOL);
        expect(maxN, `${scheme} normals, worst ${worst}`).toBeLessThan(NORMAL_TOL_DEG);
        console.log(
          `${name} ${scheme}: points ${maxPt.toExponential(2)}, positions ${maxP.toExponential(2)}, normals ${maxN.toExponential(2)}°`,
        );
        // A deformed cage: re-run only the build.
        const moved = Float64Array.from(cage.positions, (x, i) => x + 0.1 * Math.sin(3 * i));
        device.queue.writeBuffer(cageBuf, 0, Float32Array.from(moved));
        const enc2 = device.createCommandEncoder({ label: 'acc test moved' });
        gpu.encode(enc2, cageBuf);
        device.queue.submit([enc2.finish()]);
        cpu.update(moved);
        const got2 = await gpu.readPoints();
        let max2 = 0;
        for (let i = 0; i < got2.length; i++) max2 = Math.max(max2, Math.abs(got2[i] - cpu.points[i]) / diag);
        expect(max2, `${scheme} moved cage`).toBeLessThan(POSITION_TOL);
        device.queue.writeBuffer(cageBuf, 0, Float32Array.from(cage.positions));
        expect(await device.popErrorScope()).toBeNull();
        gpu.destroy();
      }
      cageBuf.destroy();
    });
  }
});
