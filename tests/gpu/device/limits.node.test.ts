/**
 * The whole pipeline (tessellate, then the renderer's shadow and main passes into an offscreen
 * texture) on devices with small limits, in Node through Dawn (SwiftShader in CI):
 *  - WebGPU's default limits only (requestDevice with no requiredLimits);
 *  - WebGPU compatibility mode (Dawn's featureLevel: 'compatibility'), whose limits are those of
 *    the specification's table (gpuweb proposals/compatibility-mode.md, "Lower limits", and the
 *    vertex/fragment-stage storage limits): checked below, so the test knows what it runs under.
 *    With the mode's own defaults it must run: the compute passes fit 128 invocations and the
 *    tessellate, shadow and lit passes read no storage in the vertex stage; the renderer leaves
 *    out what does (wireframe, patch colours, heat maps: Renderer.vertexStorage). As created by
 *    createGpu (which asks for OPTIONAL_LIMITS up to what the adapter has) it runs with all of it.
 *    And the page's canvas copy for that mode (src/gpu/render/srgb-blit.ts) encodes sRGB as an -srgb
 *    view would.
 * Table-driven over models and surfaces: a surface is one line of SURFACES.
 *
 * Node only (Dawn has compatibility mode; Chromium gives it only behind a flag).
 */
import { readFileSync } from 'node:fs';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { createGpu, OPTIONAL_LIMITS, PIPELINE_LIMITS, type GpuContext } from '../../../src/gpu/device/device.ts';
import { SRGB_TARGET_FORMAT, SrgbBlit } from '../../../src/gpu/render/srgb-blit.ts';
import { Tessellator, prepareMesh, type PreparedMesh } from '../../../src/gpu/tess/tessellator.ts';
import { Renderer } from '../../../src/gpu/render/renderer.ts';
import { uploadCageLines } from '../../../src/gpu/render/cage-mesh.ts';
import { boundsOf, cameraMatrices, fitOrbit, transformBounds, upAxisMatrix } from '../../../src/gpu/render/camera.ts';
import { headlessCamera } from '../../../src/gpu/tess/headless.ts';
import { readBuffer } from '../../../src/gpu/device/readback.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import { loadCage } from '../../../src/mesh/index.ts';
import type { Cage } from '../../../src/mesh/types.ts';
import type { CatmullClarkData } from '../../../src/gpu/cc/build.ts';

/** Compatibility mode's limits where they differ from core, as the specification lists them. */
const COMPAT_LIMITS = {
  maxColorAttachments: 4,
  maxComputeInvocationsPerWorkgroup: 128,
  maxComputeWorkgroupSizeX: 128,
  maxComputeWorkgroupSizeY: 128,
  maxInterStageShaderVariables: 15,
  maxTextureDimension1D: 4096,
  maxTextureDimension2D: 4096,
  maxUniformBufferBindingSize: 16384,
  maxStorageBuffersInVertexStage: 0,
  maxStorageTexturesInVertexStage: 0,
  maxStorageBuffersInFragmentStage: 4,
  maxStorageTexturesInFragmentStage: 4,
} as const;

/** WebGPU's default limits that bound the output buffers. */
const DEFAULT_STORAGE_BINDING = 128 * 2 ** 20;
const DEFAULT_BUFFER = 256 * 2 ** 20;

/** The surfaces to run: the data each needs beside the prepared mesh. */
const SURFACES: { surface: 'phong' | 'catmull-clark'; data(cage: Cage, mesh: PreparedMesh): CatmullClarkData | undefined }[] = [
  { surface: 'phong', data: () => undefined },
];
const MODELS = ['torus', 'creased-box'];

const W = 128;
const H = 96;
const FORMAT: GPUTextureFormat = 'rgba8unorm-srgb';
const tables = bakeTables(64);

let gpu: GPU;
const devices: Record<string, GPUDevice> = {};
const contexts: GpuContext[] = [];

beforeAll(async () => {
  const name = 'webgpu'; // indirection keeps Vite from bundling dawn.node
  const { create, globals } = await import(/* @vite-ignore */ name);
  Object.assign(globalThis, globals);
  gpu = create([]) as GPU;
  const core = (await gpu.requestAdapter())!;
  devices['default limits'] = await core.requestDevice({ label: 'default limits' });
  const compat = (await gpu.requestAdapter({ featureLevel: 'compatibility' }))!;
  devices['compatibility mode, its defaults'] = await compat.requestDevice({ label: 'compatibility defaults' });
  const ctx = await createGpu({ gpu, featureLevel: 'compatibility' });
  contexts.push(ctx);
  devices['compatibility mode, from createGpu'] = ctx.device;
});

afterAll(() => {
  for (const d of Object.values(devices)) d.destroy();
});

function cageOf(model: string): Cage {
  return loadCage(readFileSync(new URL(`../../../public/models/${model}.obj`, import.meta.url), 'utf8')).cage;
}

/** Tessellate `cage` and draw it; the validation errors, the counts and the picture. */
async function runPipeline(device: GPUDevice, cage: Cage, s: (typeof SURFACES)[number]) {
  const errors: string[] = [];
  device.pushErrorScope('validation');
  device.pushErrorScope('out-of-memory');
  const tess = Tessellator.create(device, tables, { surface: s.surface, vertexCapacity: 100_000, triangleCapacity: 100_000 });
  const mesh = prepareMesh(cage);
  tess.setMesh(mesh, s.data(cage, mesh));
  const modelMatrix = upAxisMatrix('y') as Float32Array; // the project's models are stored Y-up
  const bounds = transformBounds(boundsOf(cage.positions), modelMatrix);
  const renderer = Renderer.create(device, { colorFormat: FORMAT, shadowMapSize: 512 });
  renderer.setMesh(tess.output);
  const lines = uploadCageLines(device, cage);
  renderer.setCage(lines);
  renderer.setBounds(bounds);
  const m = cameraMatrices(fitOrbit(bounds, W / H), W / H);
  const target = device.createTexture({
    label: 'limits test target',
    size: [W, H],
    format: FORMAT,
    usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC,
  });
  const bytesPerRow = 256 * Math.ceil((4 * W) / 256);
  const read = device.createBuffer({
    label: 'limits test pixels',
    size: bytesPerRow * H,
    usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
  });
  const encoder = device.createCommandEncoder({ label: 'limits test frame' });
  tess.encode(encoder, headlessCamera(mesh, { mode: 'adaptive' }));
  renderer.render(
    encoder,
    target,
    { viewProj: m.viewProj as Float32Array, model: modelMatrix, eye: m.eye },
    { wireframe: true, cage: true },
  );
  encoder.copyTextureToBuffer({ texture: target }, { buffer: read, bytesPerRow }, [W, H]);
  device.queue.submit([encoder.finish()]);
  for (const e of [await device.popErrorScope(), await device.popErrorScope()]) if (e) errors.push(e.message);
  let counts: Uint32Array | null = null;
  let pixels: Uint8Array | null = null;
  if (!errors.length) {
    counts = new Uint32Array(await readBuffer(device, tess.output.counts, 16));
    await read.mapAsync(GPUMapMode.READ);
    pixels = new Uint8Array(read.getMappedRange().slice(0));
    read.unmap();
  }
  const vertexStorage = renderer.vertexStorage;
  renderer.destroy();
  tess.destroy();
  lines.vertices.destroy();
  target.destroy();
  read.destroy();
  const at = (x: number, y: number) => Array.from(pixels!.subarray(y * bytesPerRow + 4 * x, y * bytesPerRow + 4 * x + 4));
  return { errors, counts, at, vertexStorage };
}

describe('the devices are what they say', () => {
  it('default limits: the output buffers are bound by 128 MiB bindings and 256 MiB buffers', () => {
    const d = devices['default limits'];
    expect(d.limits.maxStorageBufferBindingSize).toBe(DEFAULT_STORAGE_BINDING);
    expect(d.limits.maxBufferSize).toBe(DEFAULT_BUFFER);
    expect(d.features.has('core-features-and-limits')).toBe(true);
  });

  it('compatibility mode: the specification’s limits; createGpu raises only OPTIONAL_LIMITS, up to the adapter’s', async () => {
    const plain = devices['compatibility mode, its defaults'];
    const ours = devices['compatibility mode, from createGpu'];
    expect(PIPELINE_LIMITS).toEqual({});
    expect(plain.features.has('core-features-and-limits')).toBe(false);
    expect(ours.features.has('core-features-and-limits')).toBe(false);
    expect(contexts[0].compatibility).toBe(true);
    const adapter = (await gpu.requestAdapter({ featureLevel: 'compatibility' }))!;
    for (const [name, value] of Object.entries(COMPAT_LIMITS)) {
      expect(plain.limits[name as keyof GPUSupportedLimits], name).toBe(value);
      const wanted = (OPTIONAL_LIMITS as Record<string, number | undefined>)[name];
      const max = adapter.limits[name as keyof GPUSupportedLimits] as number;
      expect(ours.limits[name as keyof GPUSupportedLimits], name).toBe(wanted === undefined ? value : Math.min(wanted, max));
    }
    expect(ours.limits.maxStorageBufferBindingSize).toBe(DEFAULT_STORAGE_BINDING);
  });

  it('compatibility mode: the page’s canvas copy (SrgbBlit) writes what an -srgb view would, within 1/255', async () => {
    const device = devices['compatibility mode, its defaults'];
    device.pushErrorScope('validation');
    const blit = new SrgbBlit(device, 'rgba8unorm');
    const src = blit.target(64, 4);
    // Linear ramps written into the -srgb picture (stored encoded), then copied to a plain target.
    const texels = new Uint8Array(64 * 4 * 4);
    for (let i = 0; i < texels.length; i++) texels[i] = (i * 37) % 256;
    for (let i = 3; i < texels.length; i += 4) texels[i] = 255;
    device.queue.writeTexture({ texture: src }, texels, { bytesPerRow: 256 }, [64, 4]);
    const dst = device.createTexture({
      label: 'blit test canvas',
      size: [64, 4],
      format: 'rgba8unorm',
      usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC,
    });
    const read = device.createBuffer({
      label: 'blit test pixels',
      size: 256 * 4,
      usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
    });
    const encoder = device.createCommandEncoder({ label: 'blit test' });
    blit.encode(encoder, dst);
    encoder.copyTextureToBuffer({ texture: dst }, { buffer: read, bytesPerRow: 256 }, [64, 4]);
    device.queue.submit([encoder.finish()]);
    expect((await device.popErrorScope())?.message).toBeUndefined();
    await read.mapAsync(GPUMapMode.READ);
    const out = new Uint8Array(read.getMappedRange().slice(0));
    read.unmap();
    expect(SRGB_TARGET_FORMAT).toBe('rgba8unorm-srgb');
    let worst = 0;
    for (let i = 0; i < texels.length; i++) worst = Math.max(worst, Math.abs(out[i] - texels[i]));
    expect(worst).toBeLessThanOrEqual(1);
    blit.destroy();
    dst.destroy();
    read.destroy();
  });
});

describe.each(SURFACES)('the pipeline with the $surface surface', (s) => {
  for (const device of ['default limits', 'compatibility mode, its defaults', 'compatibility mode, from createGpu']) {
    it.each(MODELS)(`runs on ${device}: %s tessellated and drawn, no validation errors`, async (model) => {
      const r = await runPipeline(devices[device], cageOf(model), s);
      expect(r.errors).toEqual([]);
      const [vertices, triangles] = r.counts!;
      expect(triangles).toBeGreaterThan(prepareMesh(cageOf(model)).triangleCount);
      expect(vertices).toBeGreaterThan(0);
      expect(new Float32Array(r.counts!.buffer)[2]).toBe(1); // within budget
      // The model in the middle, lit, differs from the backdrop in the corner.
      const centre = r.at(W / 2, H / 2);
      const corner = r.at(1, 1);
      expect(centre).not.toEqual(corner);
    });
  }

  it('on compatibility mode’s own limits the renderer leaves out what reads storage in the vertex stage, and only that', async () => {
    const compat = await runPipeline(devices['compatibility mode, its defaults'], cageOf(MODELS[0]), s);
    const core = await runPipeline(devices['default limits'], cageOf(MODELS[0]), s);
    expect(compat.errors).toEqual([]);
    expect(compat.vertexStorage).toBe(false);
    expect(core.vertexStorage).toBe(true);
  });
});
