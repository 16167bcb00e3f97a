/**
 * The instanced power-of-two tessellator (src/gpu/instanced.ts) on a WebGPU adapter, against the
 * CPU: bucket draw records and levels equal the CPU's count (static and random per-patch levels);
 * the headless pass (the draw's own vertex function, in compute) on project models at random
 * per-patch levels puts every vertex where the CPU snap and Phong surface put it (f32 tolerance),
 * flips no triangle, and closes every shared cage edge: the snapped points of its two sides pair
 * one to one and coincide within 1e-6 of the model's size (every project model on Phong; every model
 * ACC takes with each ACC scheme); a lit and a shadow draw run clean, alone and in the renderer.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { mat4 } from 'gl-matrix';
import { getDevice, releaseDevice } from './gpu-device.ts';
import { loadCage } from '../src/mesh/index.ts';
import { prepareMesh } from '../src/gpu/prepare.ts';
import { phongPoint } from '../src/gpu/phong.ts';
import {
  InstancedTessellator,
  prepareInstanced,
  cpuLevels,
  patchTriangle,
  snapPatchVertex,
  patchDomain,
  patchEdgeIds,
  patchCanonical,
  cpuDynamicEdgeLevel,
  instancedVertexParams,
  BUCKETS,
  type InstancedMesh,
  type HeadlessInstanced,
  type LevelParams,
} from '../src/gpu/instanced.ts';
import { vertexEdges, POW2_LEVEL_COUNT } from '../src/pattern/pow2.ts';
import { Renderer } from '../src/gpu/renderer.ts';
import { AccPatches } from '../src/gpu/acc.ts';
import { ACC_SCHEMES } from '../src/subdiv/acc.ts';
import { readBuffer } from '../src/gpu/readback.ts';
import { upAxisMatrix } from '../src/gpu/camera.ts';
import { boundsOf } from '../src/gpu/camera.ts';
import creature from '../public/models/creature.obj?raw';
import gear from '../public/models/gear.obj?raw';
import icosphere from '../public/models/icosphere.obj?raw';
import torus from '../public/models/torus.obj?raw';
import pawn from '../public/models/pawn.obj?raw';
import sheet from '../public/models/sheet.obj?raw';
import creasedBox from '../public/models/creased-box.obj?raw';
import brickBox from '../public/models/brick-box.obj?raw';

afterAll(() => releaseDevice());

let shared: InstancedTessellator | undefined;
afterAll(() => shared?.destroy());
async function tessellator(): Promise<InstancedTessellator> {
  shared ??= new InstancedTessellator(await getDevice());
  return shared;
}

function rng(seed: number) {
  return () => (seed = (Math.imul(seed, 1103515245) + 12345) >>> 0) / 2 ** 32;
}
function randomLevels(n: number, max: number, seed: number): Uint32Array {
  const r = rng(seed);
  const choices = [1, 2, 4, 8, 16, 32, 64].filter((l) => l <= max);
  return Uint32Array.from({ length: n }, () => choices[Math.floor(r() * choices.length)]);
}

function load(text: string): InstancedMesh {
  const cage = loadCage(text).cage;
  return prepareInstanced(cage, prepareMesh(cage));
}

function camera(m: InstancedMesh, distance: number): { viewProj: Float32Array; eye: [number, number, number] } {
  const pr = m.prepared;
  const c = [0, 1, 2].map((i) => (pr.bboxMin[i] + pr.bboxMax[i]) / 2) as [number, number, number];
  const eye: [number, number, number] = [c[0] + 0.4 * distance, c[1] + 0.5 * distance, c[2] + distance];
  const view = mat4.lookAt(mat4.create(), eye, c, [0, 1, 0]);
  const proj = mat4.perspectiveZO(mat4.create(), Math.PI / 4, 1, 0.01 * pr.size, 100 * pr.size);
  return { viewProj: mat4.multiply(mat4.create(), proj, view) as Float32Array, eye };
}

/**
 * Every check of the headless output against the CPU; returns the largest gap across an edge
 * (in units of the model's size) and the largest position error.
 */
function checkHeadless(
  m: InstancedMesh,
  out: HeadlessInstanced,
  tess: InstancedTessellator,
  phong = true,
): { gap: number; posError: number; edgesChecked: number } {
  const size = m.prepared.size;
  const { edgeLevels, patchLevels } = out;
  // Edge level = min over its patches' levels (modes static, per-patch) or ≤ each patch's level
  // (dynamic): never above a patch's level.
  for (let p = 0; p < m.patchCount; p++) for (const e of patchEdgeIds(m, p)) expect(edgeLevels[e]).toBeLessThanOrEqual(patchLevels[p]);

  // Walk the output as the GPU laid it out: bucket by bucket, instance by instance, the whole
  // pattern of each; the instance order within a bucket is the atomics' order, so each block's
  // patch is read from the output and checked to be in that bucket.
  const seen = new Uint8Array(m.patchCount);
  // Per edge and side (patch): canonical parameter → position.
  const sides = new Map<number, Map<number, Map<number, number[]>>>();
  let v0 = 0,
    t0 = 0,
    posError = 0;
  tess.patterns.entries.forEach((entry, b) => {
    const P = entry.level;
    const pattern = tess.patterns.ij.subarray(entry.baseVertex, entry.baseVertex + entry.vertexCount);
    const local = tess.patterns.indices.subarray(entry.firstIndex, entry.firstIndex + entry.indexCount);
    for (let inst = 0; inst < out.counts[b]; inst++) {
      const p = out.patch[v0];
      expect(seen[p]).toBe(0);
      seen[p] = 1;
      expect(patchDomain(m, p)).toBe(entry.domain);
      expect(patchLevels[p]).toBe(P);
      const snappedIJ: [number, number][] = [];
      for (let k = 0; k < entry.vertexCount; k++) {
        const v = v0 + k;
        expect(out.patch[v]).toBe(p);
        const [i, j] = snapPatchVertex(m, p, P, pattern[k] & 0xffff, pattern[k] >>> 16, edgeLevels);
        snappedIJ.push([i, j]);
        // The GPU's snapped parameter, exactly.
        expect([out.uv[2 * v], out.uv[2 * v + 1]]).toEqual([i / P, j / P]);
        const { t, w } = patchTriangle(m, p, P, i, j);
        const ref = phong ? phongPoint(m.prepared, t, [w[0] / 65536, w[1] / 65536, w[2] / 65536]) : null;
        for (let c = 0; c < 3; c++) {
          const x = out.positions[3 * v + c],
            n = out.normals[3 * v + c];
          if (!Number.isFinite(x) || !Number.isFinite(n)) throw new Error(`NaN or infinity at vertex ${v}`);
          if (ref) posError = Math.max(posError, Math.abs(x - ref.pos[c]) / size);
        }
        // Boundary points, by edge, side and canonical parameter.
        const dom = patchDomain(m, p),
          can = patchCanonical(m, p),
          ids = patchEdgeIds(m, p);
        for (const { edge, t: te } of vertexEdges(dom, P, i, j)) {
          const e = ids[edge];
          const cpar = can[edge] ? te / P : 1 - te / P;
          let bySide = sides.get(e);
          if (!bySide) sides.set(e, (bySide = new Map()));
          let pts = bySide.get(p);
          if (!pts) bySide.set(p, (pts = new Map()));
          const pos = [out.positions[3 * v], out.positions[3 * v + 1], out.positions[3 * v + 2]];
          const prev = pts.get(cpar);
          // A side evaluates the same parameter to the same bits, however many fine vertices
          // snapped onto it.
          if (prev) expect(pos).toEqual(prev);
          else pts.set(cpar, pos);
        }
      }
      // Triangles: the pattern's, offset to this block; none flipped in the snapped (u, v).
      const nt = entry.indexCount / 3;
      for (let q = 0; q < nt; q++) {
        const tri = [0, 1, 2].map((c) => out.indices[3 * (t0 + q) + c]);
        expect(tri).toEqual([0, 1, 2].map((c) => v0 + local[3 * q + c]));
        const [a, bb, c] = tri.map((x) => snappedIJ[x - v0]);
        const area2 = (bb[0] - a[0]) * (c[1] - a[1]) - (bb[1] - a[1]) * (c[0] - a[0]);
        expect(area2).toBeGreaterThanOrEqual(0);
      }
      v0 += entry.vertexCount;
      t0 += nt;
    }
  });
  expect(v0).toBe(out.vertexCount);
  expect(t0).toBe(out.triangleCount);
  expect(seen.every((x) => x === 1)).toBe(true);

  // Cracks: along every edge shared by two patches, both sides hold exactly the points
  // {j / L_e} and pair up one to one; report the largest distance between partners.
  let gap = 0,
    edgesChecked = 0;
  for (const [e, bySide] of sides) {
    const L = edgeLevels[e];
    const expected = Array.from({ length: L + 1 }, (_, j) => j / L);
    for (const pts of bySide.values()) expect([...pts.keys()].sort((x, y) => x - y)).toEqual(expected);
    if (bySide.size < 2) continue;
    const [a, b] = [...bySide.values()];
    for (const c of expected) {
      const pa = a.get(c)!,
        pb = b.get(c)!;
      gap = Math.max(gap, Math.hypot(pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]) / size);
    }
    edgesChecked++;
  }
  return { gap, posError, edgesChecked };
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
      // quad's split maps back as src/gpu/face-params.ts inverts it, which the exact surfaces use).
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
