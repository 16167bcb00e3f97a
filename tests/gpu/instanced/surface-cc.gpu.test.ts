/**
 * The instanced tessellator on the exact Catmull-Clark surface (src/gpu/instanced/surface-cc.ts) on a
 * WebGPU adapter: at random per-patch levels on creature (quads and triangles, extraordinary
 * vertices) and pawn (n-gons: fan triangles, the evaluator's n-gon parameter), every headless
 * output vertex (the draw's own vertex function, in compute) against the exact CPU limit
 * (src/subdiv, through tests/support/cc-checks.ts CCReference) at its face parameter, and against the
 * compute tessellator's evaluator run by its own sampler at the same (triangle, weights); the
 * crack check of issue 11 (both sides of every shared cage edge pair up within 1e-6 of the size);
 * the dynamic level rule on this surface; the factor rule (the compute tessellator's measure) at
 * the limit of the cage vertices, against the CPU rule at the exact limit; lit, shadow and
 * wireframe draws in the renderer run clean; setMesh's refusals.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { getDevice, releaseDevice } from '../../support/gpu-device.ts';
import { camera, checkHeadless, randomLevels } from '../../support/instanced-checks.ts';
import { CCReference } from '../../support/cc-checks.ts';
import { loadCage } from '../../../src/mesh/index.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { sampleSurface } from '../../../src/gpu/tess/sample-surface.ts';
import { InstancedTessellator } from '../../../src/gpu/instanced/instanced.ts';
import { factorRuleLevels } from '../../../src/gpu/instanced/instanced-options.ts';
import { prepareInstanced, patchDomain, type InstancedMesh } from '../../../src/gpu/instanced/prepare-patches.ts';
import { patchTriangle, cpuLevels, cpuFactorRuleEdgeLevel } from '../../../src/gpu/instanced/cpu-twin.ts';
import type { HeadlessInstanced } from '../../../src/gpu/instanced/headless-output.ts';
import { edgePoint } from '../../../src/pattern/pow2.ts';
import { ccEvaluatorWgsl, ccSurfaceTessellator } from '../../../src/gpu/instanced/surface-cc.ts';
import type { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { Renderer } from '../../../src/gpu/render/renderer.ts';
import { boundsOf, upAxisMatrix } from '../../../src/gpu/render/camera.ts';
import creature from '../../../public/models/creature.obj?raw';
import pawn from '../../../public/models/pawn.obj?raw';

/** f32 bounds, as fractions of the model's size (measured: at most 6e-8 and 0.0005° on both
 * models; tests/gpu/cc/cc.gpu.test.ts allows the compute tessellator's output 1e-5 and 0.1°): outside the
 * evaluator's blended squares round extraordinary vertices, and inside them (its radial blend,
 * 2^-7 of a face, is not the exact limit). */
const POSITION_BOUND = 1e-6;
const NORMAL_BOUND_DEG = 0.01;
const BLENDED_POSITION_BOUND = 1e-4;

let tess: InstancedTessellator | undefined;
const sources: Tessellator[] = [];
afterAll(() => {
  tess?.destroy();
  for (const s of sources) s.destroy();
  return releaseDevice();
});

async function instanced(): Promise<InstancedTessellator> {
  tess ??= new InstancedTessellator(await getDevice(), { surface: 'lent-limit' });
  return tess;
}

async function setUp(text: string): Promise<{ t: InstancedTessellator; m: InstancedMesh; ref: CCReference; source: Tessellator }> {
  const t = await instanced();
  const cage = loadCage(text).cage;
  const prepared = prepareMesh(cage);
  const m = prepareInstanced(cage, prepared);
  const cc = buildCatmullClark(cage, prepared);
  const source = ccSurfaceTessellator(t.device, prepared, cc);
  sources.push(source);
  t.setMesh(m, source);
  return { t, m, ref: new CCReference(cage, prepared, cc), source };
}

/** Each output vertex's cage triangle and weights (patchTriangle of its snapped pattern point). */
function vertexItems(m: InstancedMesh, out: HeadlessInstanced) {
  return Array.from({ length: out.vertexCount }, (_, v) => {
    const p = out.patch[v],
      P = out.patchLevels[p];
    const { t, w } = patchTriangle(m, p, P, Math.round(out.uv[2 * v] * P), Math.round(out.uv[2 * v + 1] * P));
    return { t, wFixed: w, w: [w[0] / 65536, w[1] / 65536, w[2] / 65536] as [number, number, number] };
  });
}

describe('instanced tessellator, exact Catmull-Clark surface', () => {
  it('the evaluator renames are whole identifiers and complete', () => {
    const code = ccEvaluatorWgsl();
    expect(code).toMatch(/\bfn ccEvalSurface\(/);
    expect(code).not.toMatch(/\b(params|staticBuf|cageBuf|evalSurface)\b/);
    // A name the evaluator stopped using is reported, not silently skipped.
    expect(() => ccEvaluatorWgsl('fn f() {}')).toThrow(/no longer uses/);
  });

  for (const [name, text, max] of [
    ['creature', creature, 16],
    ['pawn', pawn, 8],
  ] as const) {
    it(`${name}, random per-patch levels up to ${max}: every vertex on the exact limit, the compute tessellator's evaluator bit for bit, no crack`, async () => {
      const { t, m, ref, source } = await setUp(text);
      const device = t.device;
      const wanted = randomLevels(m.patchCount, max, 11 + name.length);
      t.setWanted(wanted);
      device.pushErrorScope('validation');
      const out = await t.headless({ mode: 'per-patch' });
      expect((await device.popErrorScope())?.message).toBeUndefined();
      expect(Array.from(out.records)).toEqual(Array.from(cpuLevels(m, wanted, t.patterns).records));
      const r = checkHeadless(m, out, t, false);

      const items = vertexItems(m, out);
      const cmp = ref.compare(items, out.positions, out.normals);
      // The same WGSL evaluator over the same buffers, run by the compute tessellator's sampler.
      const gpu = await sampleSurface(
        source,
        items.map(({ t: tri, wFixed }) => ({ t: tri, w1: wFixed[1], w2: wFixed[2] })),
      );
      let vsCompute = 0;
      for (let k = 0; k < 3 * out.vertexCount; k++) vsCompute = Math.max(vsCompute, Math.abs(out.positions[k] - gpu.pos[k]));
      console.log(
        `${name} catmull-clark: ${m.patchCount} patches, ${out.vertexCount} vertices, ${out.triangleCount} triangles; ` +
          `exact region ${cmp.exact.count} vertices: max ${cmp.exact.maxP.toExponential(2)} of the size, normals ${cmp.exact.maxN.toFixed(4)}°; ` +
          `blended ${cmp.blended.count}: max ${cmp.blended.maxP.toExponential(2)}; against the compute evaluator ${vsCompute.toExponential(2)}; ` +
          `${r.edgesChecked} shared edges, largest gap ${r.gap.toExponential(2)} of the size`,
      );
      expect(cmp.nan).toBe(0);
      expect(cmp.exact.count).toBeGreaterThan(0.9 * out.vertexCount);
      expect(cmp.exact.maxP, cmp.exact.worst).toBeLessThan(POSITION_BOUND);
      expect(cmp.exact.maxN, cmp.exact.worstN).toBeLessThan(NORMAL_BOUND_DEG);
      expect(cmp.blended.maxP, cmp.blended.worst).toBeLessThan(BLENDED_POSITION_BOUND);
      expect(vsCompute).toBeLessThan(1e-6 * m.prepared.size);
      expect(r.edgesChecked).toBeGreaterThan(0);
      expect(r.gap).toBeLessThan(1e-6);
    });
  }

  it('dynamic levels on the limit surface (the level pass evaluates it too): crack-free; lit, shadow and wireframe draws in the renderer run clean', async () => {
    const { t, m } = await setUp(creature);
    const device = t.device;
    const cam = camera(m, 0.8 * m.prepared.size);
    device.pushErrorScope('validation');
    const out = await t.headless({ mode: 'dynamic', viewProj: cam.viewProj, viewport: [640, 360], level: 2 });
    expect((await device.popErrorScope())?.message).toBeUndefined();
    const r = checkHeadless(m, out, t, false);
    console.log(
      `creature catmull-clark, dynamic: ${out.triangleCount} triangles, levels ${[...new Set(out.edgeLevels)].sort((a, b) => a - b)}, largest gap ${r.gap.toExponential(2)}`,
    );
    expect(new Set(out.edgeLevels).size).toBeGreaterThan(1);
    expect(r.gap).toBeLessThan(1e-6);

    const renderer = Renderer.create(device, { colorFormat: 'rgba8unorm', sampleCount: 4, shadowMapSize: 256, timestamps: false });
    t.useRenderer(renderer.shadingResources);
    renderer.setDrawer(t);
    renderer.setBounds(boundsOf(m.prepared.positions));
    const target = device.createTexture({
      label: 'test cc renderer target',
      size: [64, 64],
      format: 'rgba8unorm',
      usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC,
    });
    device.pushErrorScope('validation');
    // The first frame compiles the three vertex pipelines that inline the evaluator (reported,
    // not asserted: SwiftShader's time is no measure of a GPU's).
    const started = performance.now();
    const enc = device.createCommandEncoder({ label: 'test cc renderer frame' });
    t.encodeLevels(enc, { mode: 'static', level: 4 });
    renderer.render(
      enc,
      target,
      { viewProj: cam.viewProj, model: upAxisMatrix('y') as Float32Array, eye: cam.eye },
      { wireframe: true, cage: false },
    );
    const read = device.createBuffer({
      label: 'test cc renderer read',
      size: 64 * 64 * 4,
      usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ,
    });
    enc.copyTextureToBuffer({ texture: target }, { buffer: read, bytesPerRow: 256 }, [64, 64]);
    device.queue.submit([enc.finish()]);
    expect((await device.popErrorScope())?.message).toBeUndefined();
    await read.mapAsync(GPUMapMode.READ);
    console.log(
      `creature catmull-clark: first renderer frame (lit, shadow and wireframe pipelines made and drawn) ${(performance.now() - started).toFixed(0)} ms`,
    );
    const px = new Uint8Array(read.getMappedRange().slice(0));
    read.unmap();
    let bright = 0;
    for (let k = 0; k < 64 * 64; k++) if (px[4 * k] + px[4 * k + 1] + px[4 * k + 2] > 300) bright++;
    expect(bright).toBeGreaterThan(64 * 64 * 0.05);
    target.destroy();
    read.destroy();
    renderer.destroy();
  });

  it("factor-rule levels on the limit: each edge's level is the compute tessellator's rule at the exact limit of its ends (CPU), rounded up to a power of two; crack-free", async () => {
    const { t, m, ref } = await setUp(creature);
    const cam = camera(m, 1.2 * m.prepared.size);
    const lp = factorRuleLevels({
      mode: 'adaptive',
      fixedFactor: 1,
      lodScale: 2,
      viewProj: cam.viewProj,
      eye: cam.eye,
      viewportHeight: 720,
      fovY: Math.PI / 4,
    });
    const out = await t.headless(lp);
    // The exact limit position and normal at every cage vertex, from a patch corner that has it.
    const limit = new Map<number, { pos: [number, number, number]; normal: [number, number, number] }>();
    for (let p = 0; p < m.patchCount; p++) {
      const dom = patchDomain(m, p);
      for (let k = 0; k < (dom === 'tri' ? 3 : 4); k++) {
        const v = m.corners[4 * p + k];
        if (limit.has(v)) continue;
        const [i, j] = edgePoint(dom, 1, k, 0);
        const { t: tri, w } = patchTriangle(m, p, 1, i, j);
        const r = ref.at(tri, [w[0] / 65536, w[1] / 65536, w[2] / 65536]).ref;
        limit.set(v, { pos: r.P, normal: r.N });
      }
    }
    let compared = 0;
    for (let e = 0; e < m.edgeCount; e++) {
      const cpu = cpuFactorRuleEdgeLevel(m, e, lp, (v) => limit.get(v)!);
      // Skip a factor within f32 noise of an integer (where rounding up may go either way).
      if (Math.abs(cpu.f - Math.round(cpu.f)) < 1e-4 * cpu.f && cpu.f > 1) continue;
      expect(out.edgeLevels[e]).toBe(cpu.level);
      compared++;
    }
    expect(compared).toBeGreaterThan(0.99 * m.edgeCount);
    expect(new Set(out.edgeLevels).size).toBeGreaterThan(1);
    const r = checkHeadless(m, out, t, false);
    console.log(
      `creature catmull-clark, factor rule (lod 2): ${out.triangleCount} triangles drawn, levels ${[...new Set(out.edgeLevels)].sort((a, b) => a - b)}, largest gap ${r.gap.toExponential(2)}`,
    );
    expect(r.gap).toBeLessThan(1e-6);
  });

  it('setMesh refuses a lending tessellator that blends to the flat baseline or holds another mesh', async () => {
    const t = await instanced();
    const cage = loadCage(creature).cage;
    const prepared = prepareMesh(cage);
    const source = ccSurfaceTessellator(t.device, prepared, buildCatmullClark(cage, prepared));
    sources.push(source);
    const m = prepareInstanced(cage, prepared);
    source.flatBaseline = true;
    expect(() => t.setMesh(m, source)).toThrow(/flatBaseline/);
    source.flatBaseline = false;
    const other = loadCage(pawn).cage;
    expect(() => t.setMesh(prepareInstanced(other, prepareMesh(other)), source)).toThrow(/another mesh/);
    expect(() => t.setMesh(m)).toThrow(/Catmull-Clark Tessellator/);
  });
});
