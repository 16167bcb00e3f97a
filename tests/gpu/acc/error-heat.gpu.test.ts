/**
 * The demo's ACC error views on the GPU (src/gpu/acc/heat.ts, wgsl/acc/heat.wgsl): after an ACC
 * tessellator's rebuild, the pass over its output vertices. Each vertex's value is held, element
 * by element, against the f64 CPU references at the vertex's own cage parameter (srcTri, bary →
 * accFaceParam; src/subdiv/acc.ts AccSurface against the exact evaluator), with the tolerances
 * of tests/gpu/acc/error.gpu.test.ts (1.2e-4 of the diagonal; 0.12° outside the exact GPU evaluator's
 * blended corner regions); vertices of regular patches are exactly 0 (the pass skips them: the
 * schemes are exact there); the totals read back are the max and RMS of those values (f32 sums:
 * 1e-4 relative). The regular torus gives 0 everywhere. And the renderer's heat colours
 * (Renderer.setHeat, wgsl/render/heat.wgsl): per-vertex values at 0, half and all of the range
 * come out as the ramp's blue, green and red; the view picks the value; no values, no change.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { CCReference } from '../../support/cc-checks.ts';
import { ExactAt } from '../../support/acc-checks.ts';
import { angleBetween } from '../../support/tess-checks.ts';
import { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import { accFaceParam } from '../../../src/gpu/acc/patches.ts';
import { prepareAccSurface } from '../../../src/gpu/acc/surface.ts';
import { AccHeatPass, HEAT_RAMP } from '../../../src/gpu/acc/heat.ts';
import { cageDiagonal } from '../../../src/mesh/range.ts';
import { readBuffer, readMesh } from '../../../src/gpu/device/readback.ts';
import { KIND_REGULAR, type AccScheme, accCage } from '../../../src/subdiv/acc.ts';
import { AccSurface } from '../../../src/subdiv/acc-evaluate.ts';
import { decodeBary } from '../../../src/gpu/contract/tess.ts';
import { loadCage, makeCage } from '../../../src/mesh/index.ts';
import { Renderer } from '../../../src/gpu/render/renderer.ts';
import { destroyMesh, uploadCageMesh } from '../../../src/gpu/render/cage-mesh.ts';
import { boundsOf, cameraMatrices, fitOrbit, upAxisMatrix } from '../../../src/gpu/render/camera.ts';
import creature from '../../../public/models/creature.obj?raw';
import torus from '../../../public/models/torus.obj?raw';
import icosphere from '../../../public/models/icosphere.obj?raw';

const POSITION_TOL = 1.2e-4; // × bbox diagonal
const ANGLE_TOL_DEG = 0.12;

const tables = bakeTables(64);
const made: { destroy(): void }[] = [];
afterAll(() => {
  made.forEach((t) => t.destroy());
  return releaseDevice();
});

const cases: [string, string, AccScheme, number][] = [
  ['creature', creature, 'gregory-acc', 2.5],
  ['creature', creature, 'bezier-acc', 2],
  ['torus', torus, 'pm-acc', 3],
  // Pentagons: the scheme's cage is one Catmull-Clark step of it (accCage), and so is the reference's.
  ['icosphere', icosphere, 'pm-acc', 3],
];

describe('ACC error views: per output vertex on the GPU', () => {
  for (const [name, text, scheme, factor] of cases) {
    it(`${name} ${scheme}: every vertex against the CPU, totals are its max and RMS`, async () => {
      const device = await getDevice();
      const cage = accCage(loadCage(text).cage).cage;
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

describe('heat colours in the lit pass', () => {
  const W = 96,
    H = 72;
  const cube = makeCage(
    [-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1],
    [
      [0, 3, 2, 1],
      [4, 5, 6, 7],
      [0, 1, 5, 4],
      [1, 2, 6, 5],
      [2, 3, 7, 6],
      [3, 0, 4, 7],
    ],
  );

  async function centre(
    device: GPUDevice,
    renderer: Renderer,
    heat: { view: 'geometry' | 'normal'; range: number } | null,
  ): Promise<number[]> {
    const target = device.createTexture({
      label: 'heat test target',
      size: [W, H],
      format: 'rgba8unorm-srgb',
      usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC,
    });
    const bounds = boundsOf(cube.positions);
    const m = cameraMatrices(fitOrbit(bounds, W / H), W / H);
    const enc = device.createCommandEncoder({ label: 'heat test frame' });
    renderer.render(
      enc,
      target,
      { viewProj: m.viewProj as Float32Array, model: upAxisMatrix('y') as Float32Array, eye: m.eye },
      { wireframe: false, cage: false, heat },
    );
    device.queue.submit([enc.finish()]);
    const row = 512;
    const read = device.createBuffer({
      label: 'heat test readback',
      size: row * H,
      usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
    });
    const e2 = device.createCommandEncoder({ label: 'heat test copy' });
    e2.copyTextureToBuffer({ texture: target }, { buffer: read, bytesPerRow: row }, [W, H]);
    device.queue.submit([e2.finish()]);
    await read.mapAsync(GPUMapMode.READ);
    const px = Array.from(new Uint8Array(read.getMappedRange()).subarray((H / 2) * row + (W / 2) * 4, (H / 2) * row + (W / 2) * 4 + 3));
    read.unmap();
    read.destroy();
    target.destroy();
    return px;
  }

  it('values at 0, half and all of the range are blue, green and red; the view picks the value', async () => {
    const device = await getDevice();
    device.pushErrorScope('validation');
    const renderer = Renderer.create(device, { colorFormat: 'rgba8unorm-srgb', shadowMapSize: 256 });
    const mesh = uploadCageMesh(device, cube);
    renderer.setBounds(boundsOf(cube.positions));
    renderer.setMesh(mesh);
    const values = device.createBuffer({
      label: 'heat test values',
      size: 8 * 256,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
    });
    const fill = (geometry: number, normal: number) =>
      device.queue.writeBuffer(
        values,
        0,
        Float32Array.from({ length: 512 }, (_, i) => (i % 2 ? normal : geometry)),
      );
    const plain = await centre(device, renderer, null);
    // Asked for, but no values set: the usual colours.
    expect(await centre(device, renderer, { view: 'geometry', range: 1 })).toEqual(plain);
    renderer.setHeat({ buffer: values });
    const dominant = (p: number[]) => p.indexOf(Math.max(...p));
    fill(0, 0.02);
    const blue = await centre(device, renderer, { view: 'geometry', range: 0.01 });
    fill(0.005, 0);
    const green = await centre(device, renderer, { view: 'geometry', range: 0.01 });
    fill(0.02, 0);
    const red = await centre(device, renderer, { view: 'geometry', range: 0.01 });
    // The normal view reads the second value: 0 here (blue), then 0.02 against a range of 0.01 (red).
    const normalBlue = await centre(device, renderer, { view: 'normal', range: 0.01 });
    fill(0, 0.02);
    const normalRed = await centre(device, renderer, { view: 'normal', range: 0.01 });
    expect((await device.popErrorScope())?.message).toBeUndefined();
    console.log('heat colours', { plain, blue, green, red, normalBlue, normalRed });
    expect(dominant(blue)).toBe(2);
    expect(dominant(green)).toBe(1);
    expect(dominant(red)).toBe(0);
    expect(normalBlue).toEqual(blue);
    expect(normalRed).toEqual(red);
    // Against the CPU: the ramp's stop (HEAT_RAMP, to linear as the shader: ^2.2) times one shading
    // factor (the same normal for all three), sRGB-encoded by the target: within 3 of 255.
    const toSrgb = (x: number) => 255 * (x <= 0.0031308 ? 12.92 * x : 1.055 * x ** (1 / 2.4) - 0.055);
    const fromSrgb = (c: number) => ((c /= 255) <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
    const k = fromSrgb(blue[2]) / HEAT_RAMP[0][2] ** 2.2;
    expect(k).toBeGreaterThan(0.25 - 0.01);
    expect(k).toBeLessThan(1 + 0.01);
    [blue, green, red].forEach((px, stop) => {
      for (let c = 0; c < 3; c++)
        expect(Math.abs(px[c] - toSrgb(k * HEAT_RAMP[stop][c] ** 2.2)), `stop ${stop} channel ${c}`).toBeLessThanOrEqual(3);
    });
    values.destroy();
    renderer.destroy();
    destroyMesh(mesh);
  });
});
