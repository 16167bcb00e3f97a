/**
 * The instanced power-of-two tessellator (src/gpu/instanced/instanced.ts) on a WebGPU adapter, against the
 * CPU: bucket draw records and levels equal the CPU's count (static and random per-patch levels);
 * the headless pass (the draw's own vertex function, in compute) on project models at random
 * per-patch levels puts every vertex where the CPU snap and Phong surface put it (f32 tolerance),
 * flips no triangle, and closes every shared cage edge: the snapped points of its two sides pair
 * one to one and coincide within 1e-6 of the model's size (every project model on Phong; every model
 * ACC takes with each ACC scheme); a lit and a shadow draw run clean, alone and in the renderer.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { getDevice, releaseDevice } from '../../support/gpu-device.ts';
import { camera, checkHeadless, load, randomLevels } from '../../support/instanced-checks.ts';
import { loadCage } from '../../../src/mesh/index.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { phongPoint } from '../../../src/gpu/surface/phong.ts';
import { InstancedTessellator } from '../../../src/gpu/instanced/instanced.ts';
import { factorRuleLevels, type LevelParams } from '../../../src/gpu/instanced/instanced-options.ts';
import { BUCKETS } from '../../../src/gpu/instanced/buffer-layouts.ts';
import { prepareInstanced, patchDomain, patchEdgeIds } from '../../../src/gpu/instanced/prepare-patches.ts';
import { cpuLevels, cpuDynamicEdgeLevel, cpuFactorRuleEdgeLevel } from '../../../src/gpu/instanced/cpu-twin.ts';
import { instancedVertexParams } from '../../../src/gpu/instanced/headless-output.ts';
import { POW2_LEVEL_COUNT } from '../../../src/pattern/pow2.ts';
import { Renderer } from '../../../src/gpu/render/renderer.ts';
import { AccPatches } from '../../../src/gpu/acc/patches.ts';
import { ACC_SCHEMES } from '../../../src/subdiv/acc.ts';
import { readBuffer } from '../../../src/gpu/device/readback.ts';
import { upAxisMatrix } from '../../../src/gpu/render/camera.ts';
import { boundsOf } from '../../../src/gpu/render/camera.ts';
import creature from '../../../public/models/creature.obj?raw';
import gear from '../../../public/models/gear.obj?raw';
import icosphere from '../../../public/models/icosphere.obj?raw';
import torus from '../../../public/models/torus.obj?raw';
import pawn from '../../../public/models/pawn.obj?raw';
import sheet from '../../../public/models/sheet.obj?raw';
import creasedBox from '../../../public/models/creased-box.obj?raw';
import brickBox from '../../../public/models/brick-box.obj?raw';

afterAll(() => releaseDevice());

let shared: InstancedTessellator | undefined;
afterAll(() => shared?.destroy());
async function tessellator(): Promise<InstancedTessellator> {
  shared ??= new InstancedTessellator(await getDevice());
  return shared;
}

describe('instanced tessellator', () => {
  it('bucket draw records, lists and levels equal the CPU count: static and random per-patch levels', async () => {
    const tess = await tessellator();
    const device = tess.device;
    for (const text of [creature, gear]) {
      const m = load(text);
      tess.setMesh(m);
      const cases: [LevelParams, Uint32Array][] = [
        [{ mode: 'static', level: 1 }, new Uint32Array(m.patchCount).fill(1)],
        [{ mode: 'static', level: 8 }, new Uint32Array(m.patchCount).fill(8)],
        [{ mode: 'static', level: 64 }, new Uint32Array(m.patchCount).fill(64)],
        [{ mode: 'per-patch' }, randomLevels(m.patchCount, 64, 7)],
      ];
      for (const [lp, wanted] of cases) {
        if (lp.mode === 'per-patch') tess.setWanted(wanted);
        device.pushErrorScope('validation');
        const enc = device.createCommandEncoder({ label: 'test levels' });
        tess.encodeLevels(enc, lp);
        device.queue.submit([enc.finish()]);
        expect((await device.popErrorScope())?.message).toBeUndefined();
        const gpu = await tess.readLevels();
        const cpu = cpuLevels(m, wanted, tess.patterns);
        expect(Array.from(gpu.records)).toEqual(Array.from(cpu.records));
        expect(Array.from(gpu.edgeLevels)).toEqual(Array.from(cpu.edgeLevels));
        expect(Array.from(gpu.patchLevels)).toEqual(Array.from(cpu.patchLevels));
        // Each bucket's list holds exactly its patches (in the atomics' order).
        for (let b = 0; b < BUCKETS; b++) {
          const mine = [...Array(m.patchCount).keys()].filter(
            (p) => (patchDomain(m, p) === 'tri' ? POW2_LEVEL_COUNT : 0) + Math.log2(cpu.patchLevels[p]) === b,
          );
          expect([...gpu.lists[b]].sort((x, y) => x - y)).toEqual(mine);
        }
      }
    }
  });

  // Every project model (creature-wrinkles has the creature's cage, displaced in its own work).
  const models: [string, string, number][] = [
    ['creature', creature, 16],
    ['gear', gear, 32],
    ['icosphere', icosphere, 64],
    ['pawn', pawn, 16],
    ['sheet', sheet, 64],
    ['torus', torus, 32],
    ['brick-box', brickBox, 64],
    ['creased-box', creasedBox, 64],
  ];
  for (const [name, text, max] of models) {
    it(`${name}, random per-patch levels up to ${max}: headless output on the CPU's snap and surface, no flip, no crack`, async () => {
      const tess = await tessellator();
      const m = load(text);
      tess.setMesh(m);
      tess.setWanted(randomLevels(m.patchCount, max, name.length));
      const out = await tess.headless({ mode: 'per-patch' });
      expect(Array.from(out.records)).toEqual(
        Array.from(cpuLevels(m, randomLevels(m.patchCount, max, name.length), tess.patterns).records),
      );
      const r = checkHeadless(m, out, tess);
      // Face parameters for the CLI's --params: on a quad face, exactly the patch's (u, v) (the
      // quad's split maps back as src/gpu/tess/face-params.ts inverts it, which the exact surfaces use).
      const cage = loadCage(text).cage;
      const fp = instancedVertexParams(m, cage, out);
      let quadVerts = 0;
      for (let v = 0; v < out.vertexCount; v++) {
        const q = fp[v];
        expect(q.face).toBe(m.patches[8 * out.patch[v] + 6]);
        if (!('u' in q)) continue;
        quadVerts++;
        expect(Math.abs(q.u - out.uv[2 * v]) + Math.abs(q.v - out.uv[2 * v + 1])).toBeLessThan(1e-12);
      }
      expect(quadVerts > 0).toBe(m.quadCount > 0);
      console.log(
        `${name}: ${m.patchCount} patches, ${out.vertexCount} vertices, ${out.triangleCount} triangles; ` +
          `${r.edgesChecked} shared edges, largest gap ${r.gap.toExponential(2)} of the size, largest position error ${r.posError.toExponential(2)}`,
      );
      expect(r.edgesChecked).toBeGreaterThan(0);
      expect(r.gap).toBeLessThan(1e-6);
      expect(r.posError).toBeLessThan(2e-6);
    });
  }

  it('dynamic levels: finer near the eye, each patch at its finest edge, crack-free; lit and shadow draws run clean', async () => {
    const tess = await tessellator();
    const device = tess.device;
    const m = load(creature);
    tess.setMesh(m);
    const total: number[] = [];
    for (const distance of [0.6, 3]) {
      const cam = camera(m, distance * m.prepared.size);
      const lp: LevelParams = { mode: 'dynamic', viewProj: cam.viewProj, viewport: [1280, 720], level: 2 };
      const out = await tess.headless(lp);
      // Every edge's level is the CPU rule's, except where the continuous count lies within f32
      // noise of a power of two (where rounding up may go either way).
      let compared = 0;
      for (let e = 0; e < m.edgeCount; e++) {
        const cpu = cpuDynamicEdgeLevel(m, e, lp, (t, w) => phongPoint(m.prepared, t, w).pos);
        const k = Math.round(Math.log2(cpu.n));
        if (Number.isFinite(cpu.n) && Math.abs(cpu.n - 2 ** k) < 1e-4 * 2 ** k) continue;
        expect(out.edgeLevels[e]).toBe(cpu.level);
        compared++;
      }
      expect(compared).toBeGreaterThan(0.99 * m.edgeCount);
      for (let p = 0; p < m.patchCount; p++) expect(out.patchLevels[p]).toBe(Math.max(...patchEdgeIds(m, p).map((e) => out.edgeLevels[e])));
      const r = checkHeadless(m, out, tess);
      console.log(
        `creature, dynamic at ${distance} × size: ${out.triangleCount} triangles, levels ${[...new Set(out.edgeLevels)].sort((a, b) => a - b)}, largest gap ${r.gap.toExponential(2)}`,
      );
      expect(r.gap).toBeLessThan(1e-6);
      total.push(out.triangleCount);
    }
    expect(total[0]).toBeGreaterThan(total[1]);

    // Draw: one lit pass and one shadow pass into small targets; the lit pass must cover pixels.
    const cam = camera(m, 0.8 * m.prepared.size);
    device.pushErrorScope('validation');
    const colour = device.createTexture({
      label: 'test colour',
      size: [64, 64],
      format: 'rgba8unorm',
      usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC,
    });
    const depth = device.createTexture({
      label: 'test depth',
      size: [64, 64],
      format: 'depth32float',
      usage: GPUTextureUsage.RENDER_ATTACHMENT,
    });
    const shadow = device.createTexture({
      label: 'test shadow map',
      size: [64, 64],
      format: 'depth32float',
      usage: GPUTextureUsage.RENDER_ATTACHMENT,
    });
    tess.writeFrame({ viewProj: cam.viewProj, eye: cam.eye });
    const enc = device.createCommandEncoder({ label: 'test draw' });
    tess.encodeLevels(enc, { mode: 'static', level: 4 });
    let pass = enc.beginRenderPass({
      label: 'test shadow pass',
      colorAttachments: [],
      depthStencilAttachment: {
        view: shadow.createView({ label: 'test shadow view' }),
        depthClearValue: 1,
        depthLoadOp: 'clear',
        depthStoreOp: 'store',
      },
    });
    tess.encodeDraw(pass, 'shadow');
    pass.end();
    pass = enc.beginRenderPass({
      label: 'test lit pass',
      colorAttachments: [
        { view: colour.createView({ label: 'test colour view' }), clearValue: [0, 0, 0, 0], loadOp: 'clear', storeOp: 'store' },
      ],
      depthStencilAttachment: {
        view: depth.createView({ label: 'test depth view' }),
        depthClearValue: 1,
        depthLoadOp: 'clear',
        depthStoreOp: 'discard',
      },
    });
    tess.encodeDraw(pass, 'lit');
    pass.end();
    const read = device.createBuffer({
      label: 'test colour read',
      size: 64 * 64 * 4,
      usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ,
    });
    enc.copyTextureToBuffer({ texture: colour }, { buffer: read, bytesPerRow: 256 }, [64, 64]);
    device.queue.submit([enc.finish()]);
    expect((await device.popErrorScope())?.message).toBeUndefined();
    await read.mapAsync(GPUMapMode.READ);
    const px = new Uint8Array(read.getMappedRange().slice(0));
    read.unmap();
    let covered = 0;
    for (let k = 0; k < 64 * 64; k++) if (px[4 * k + 3] === 255) covered++;
    expect(covered).toBeGreaterThan(64 * 64 * 0.05);
    for (const t of [colour, depth, shadow]) t.destroy();
    read.destroy();
  });

  it("factor-rule levels: each edge's level is the compute tessellator's adaptive factor rounded up to a power of two (the CPU rule), crack-free", async () => {
    const tess = await tessellator();
    for (const text of [creature, pawn]) {
      const m = load(text);
      tess.setMesh(m);
      const pr = m.prepared;
      const cam = camera(m, 1.2 * pr.size);
      const lp = factorRuleLevels({
        mode: 'adaptive',
        fixedFactor: 1,
        lodScale: 2,
        viewProj: cam.viewProj,
        eye: cam.eye,
        viewportHeight: 720,
        fovY: Math.PI / 4,
      });
      const out = await tess.headless(lp);
      const vec = (a: Float32Array, v: number) => [a[3 * v], a[3 * v + 1], a[3 * v + 2]] as [number, number, number];
      let compared = 0;
      for (let e = 0; e < m.edgeCount; e++) {
        const cpu = cpuFactorRuleEdgeLevel(m, e, lp, (v) => ({ pos: vec(pr.positions, v), normal: vec(pr.normals, v) }));
        // Skip a factor within f32 noise of an integer (where rounding up may go either way).
        if (Math.abs(cpu.f - Math.round(cpu.f)) < 1e-4 * cpu.f && cpu.f > 1) continue;
        expect(out.edgeLevels[e]).toBe(cpu.level);
        compared++;
      }
      expect(compared).toBeGreaterThan(0.99 * m.edgeCount);
      for (let p = 0; p < m.patchCount; p++) expect(out.patchLevels[p]).toBe(Math.max(...patchEdgeIds(m, p).map((e) => out.edgeLevels[e])));
      expect(new Set(out.edgeLevels).size).toBeGreaterThan(1);
      const r = checkHeadless(m, out, tess);
      console.log(
        `factor rule (lod 2): ${m.patchCount} patches, ${out.triangleCount} triangles drawn, levels ${[...new Set(out.edgeLevels)].sort((a, b) => a - b)}, largest gap ${r.gap.toExponential(2)}`,
      );
      expect(r.gap).toBeLessThan(1e-6);
    }
  });

  it("inside the demo renderer's passes: shadow, lit and wireframe draws run clean, cover pixels, and the wire records follow the indexed ones", async () => {
    const tess = await tessellator();
    const device = tess.device;
    const m = load(creature);
    tess.setMesh(m);
    const timed = device.features.has('timestamp-query');
    const renderer = Renderer.create(device, { colorFormat: 'rgba8unorm', sampleCount: 4, shadowMapSize: 256, timestamps: timed });
    tess.useRenderer(renderer.shadingResources);
    renderer.setDrawer(tess);
    renderer.setBounds(boundsOf(m.prepared.positions));
    const target = device.createTexture({
      label: 'test renderer target',
      size: [64, 64],
      format: 'rgba8unorm',
      usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC,
    });
    const cam = camera(m, 0.8 * m.prepared.size);
    device.pushErrorScope('validation');
    const enc = device.createCommandEncoder({ label: 'test renderer frame' });
    tess.encodeLevels(enc, { mode: 'static', level: 4 });
    renderer.render(
      enc,
      target,
      { viewProj: cam.viewProj, model: upAxisMatrix('y') as Float32Array, eye: cam.eye },
      { wireframe: true, cage: false },
    );
    const read = device.createBuffer({
      label: 'test renderer read',
      size: 64 * 64 * 4,
      usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ,
    });
    enc.copyTextureToBuffer({ texture: target }, { buffer: read, bytesPerRow: 256 }, [64, 64]);
    device.queue.submit([enc.finish()]);
    expect((await device.popErrorScope())?.message).toBeUndefined();
    await read.mapAsync(GPUMapMode.READ);
    const px = new Uint8Array(read.getMappedRange().slice(0));
    read.unmap();
    // The backdrop is dark and fairly uniform; the lit clay surface is bright.
    let bright = 0;
    for (let k = 0; k < 64 * 64; k++) if (px[4 * k] + px[4 * k + 1] + px[4 * k + 2] > 300) bright++;
    expect(bright).toBeGreaterThan(64 * 64 * 0.05);
    const args = new Uint32Array(await readBuffer(device, tess.drawArgs, 36 * BUCKETS));
    for (let b = 0; b < BUCKETS; b++) {
      expect(Array.from(args.subarray(5 * BUCKETS + 4 * b, 5 * BUCKETS + 4 * b + 4))).toEqual([2 * args[5 * b], args[5 * b + 1], 0, 0]);
    }

    await renderer.readTimings(); // the first frame's, so that the split frame's are copied
    // The split view: two regions, the stored-mesh half drawn by nothing here (no mesh set), the
    // instanced half by the drawer; both timing slots come back.
    device.pushErrorScope('validation');
    const split = device.createCommandEncoder({ label: 'test split frame' });
    const view = { viewProj: cam.viewProj, model: upAxisMatrix('y') as Float32Array, eye: cam.eye };
    renderer.setDrawer(null);
    renderer.render(split, target, view, { wireframe: false, cage: false, region: { x0: 0, x1: 0.5, first: true, slot: 0 } });
    renderer.setDrawer(tess);
    renderer.render(split, target, view, { wireframe: true, cage: false, region: { x0: 0.5, x1: 1, first: false, slot: 1 } });
    device.queue.submit([split.finish()]);
    expect((await device.popErrorScope())?.message).toBeUndefined();
    if (timed) expect(Object.keys(await renderer.readTimings()).sort()).toEqual(['lit', 'lit 2', 'shadow', 'shadow 2']);
    target.destroy();
    read.destroy();
    renderer.destroy();
  });

  // The project's models ACC takes (closed, quads and triangles; gear, icosphere and pawn have
  // n-gons, the sheet a boundary), one tessellator for all (SwiftShader compiles it once).
  let accTess: InstancedTessellator | undefined;
  afterAll(() => accTess?.destroy());
  for (const [name, text] of [
    ['creature', creature],
    ['torus', torus],
    ['creased-box', creasedBox],
    ['brick-box', brickBox],
  ] as const) {
    it(`ACC surfaces, ${name}: every scheme at random per-patch levels, each vertex where AccPatches.sample puts its face parameter, no crack`, async () => {
      const device = await getDevice();
      accTess ??= new InstancedTessellator(device, { surface: 'acc' });
      const tess = accTess;
      const cage = loadCage(text).cage;
      const m = prepareInstanced(cage, prepareMesh(cage));
      for (const scheme of ACC_SCHEMES) {
        const acc = new AccPatches(device, cage, scheme);
        device.pushErrorScope('validation');
        tess.setMesh(m, acc);
        tess.setWanted(randomLevels(m.patchCount, 16, 5));
        const out = await tess.headless({ mode: 'per-patch' });
        const r = checkHeadless(m, out, tess, false);
        // The same evaluator at the same face parameter (a patch is a cage face; (u, v) = (i, j) / P).
        const pts = Array.from(
          { length: out.vertexCount },
          (_, v) => [m.patches[8 * out.patch[v] + 6], out.uv[2 * v], out.uv[2 * v + 1]] as [number, number, number],
        );
        const ref = await acc.sample(pts);
        let posError = 0;
        for (let k = 0; k < 3 * out.vertexCount; k++)
          posError = Math.max(posError, Math.abs(out.positions[k] - ref.pos[k]) / m.prepared.size);
        // The dynamic rule evaluates the surface too (its ACC buffers bound in the level pass).
        const cam = camera(m, 0.8 * m.prepared.size);
        const dyn =
          scheme === ACC_SCHEMES[0]
            ? await tess.headless({ mode: 'dynamic', viewProj: cam.viewProj, viewport: [1280, 720], level: 2 })
            : out;
        const rd = checkHeadless(m, dyn, tess, false);
        expect((await device.popErrorScope())?.message).toBeUndefined();
        console.log(
          `${name} ${scheme}: ${out.triangleCount} triangles, ${r.edgesChecked} shared edges, largest gap ${r.gap.toExponential(2)} of the size (dynamic: ${rd.gap.toExponential(2)}), against AccPatches.sample ${posError.toExponential(2)}`,
        );
        expect(r.edgesChecked).toBeGreaterThan(0);
        expect(posError).toBeLessThan(1e-6);
        expect(r.gap).toBeLessThan(1e-6);
        expect(rd.gap).toBeLessThan(1e-6);
        acc.destroy();
      }
    });
  }
});
