/**
 * The renderer and the device setup on a real WebGPU adapter (Dawn in Node, headless Chromium in
 * the browser project; SwiftShader in CI): no validation errors, and pixels where they belong —
 * the model in the middle, the backdrop in the corners, the overlays changing the picture.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { createGpu, GpuUnavailableError, type GpuContext } from '../../../src/gpu/device/device.ts';
import { Renderer, type View } from '../../../src/gpu/render/renderer.ts';
import { destroyMesh, uploadCageLines, uploadCageMesh } from '../../../src/gpu/render/cage-mesh.ts';
import { boundsOf, cameraMatrices, fitOrbit, upAxisMatrix } from '../../../src/gpu/render/camera.ts';
import { makeCage } from '../../../src/mesh/types.ts';

// Dawn's GPU object must outlive its devices: keep it referenced for the whole file.
let gpuObject: GPU | undefined;
let ctx: GpuContext;

async function gpuEntry(): Promise<GPU> {
  const nav = (globalThis as { navigator?: { gpu?: GPU } }).navigator?.gpu;
  if (nav) return nav;
  const name = 'webgpu'; // indirection keeps Vite from bundling dawn.node for the browser
  const { create, globals } = await import(/* @vite-ignore */ name);
  Object.assign(globalThis, globals);
  return create([]) as GPU;
}

beforeAll(async () => {
  gpuObject = await gpuEntry();
  // More than any adapter has: the device gets the adapter's maximum, and says it was clamped.
  ctx = await createGpu({ gpu: gpuObject, wantedLimits: { maxStorageBufferBindingSize: 2 ** 40, maxBufferSize: 2 ** 40 } });
});
afterAll(() => {
  ctx?.destroy();
  gpuObject = undefined;
});

const W = 160;
const H = 120;
const FORMAT: GPUTextureFormat = 'rgba8unorm-srgb';

// A cube from -1 to 1 with one crease, faces counter-clockwise seen from outside.
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
  { creases: [[4, 5, 10]] },
);

function view(): View {
  const bounds = boundsOf(cube.positions);
  const m = cameraMatrices(fitOrbit(bounds, W / H), W / H);
  return { viewProj: m.viewProj as Float32Array, model: upAxisMatrix('y') as Float32Array, eye: m.eye };
}

/** Render one frame and read it back as RGBA8 rows (tightly packed). */
async function draw(renderer: Renderer, options: { wireframe: boolean; cage: boolean; patchColours?: boolean }): Promise<Uint8Array> {
  const device = ctx.device;
  const target = device.createTexture({
    label: 'test target',
    size: [W, H],
    format: FORMAT,
    usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC,
  });
  const bytesPerRow = Math.ceil((W * 4) / 256) * 256;
  const read = device.createBuffer({
    label: 'test readback',
    size: bytesPerRow * H,
    usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
  });
  const encoder = device.createCommandEncoder({ label: 'test frame' });
  renderer.render(encoder, target, view(), options);
  encoder.copyTextureToBuffer({ texture: target }, { buffer: read, bytesPerRow }, [W, H]);
  device.queue.submit([encoder.finish()]);
  await read.mapAsync(GPUMapMode.READ);
  const padded = new Uint8Array(read.getMappedRange());
  const pixels = new Uint8Array(W * H * 4);
  for (let y = 0; y < H; y++) pixels.set(padded.subarray(y * bytesPerRow, y * bytesPerRow + W * 4), y * W * 4);
  read.unmap();
  read.destroy();
  target.destroy();
  return pixels;
}

const pixel = (img: Uint8Array, x: number, y: number) => Array.from(img.subarray((y * W + x) * 4, (y * W + x) * 4 + 4));
const luma = (p: number[]) => 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
function differing(a: Uint8Array, b: Uint8Array): number {
  let n = 0;
  for (let i = 0; i < a.length; i += 4) if (a[i] !== b[i] || a[i + 1] !== b[i + 1] || a[i + 2] !== b[i + 2]) n++;
  return n;
}

describe('device', () => {
  it('raises the wanted buffer limits up to the adapter maximum, says what it clamped, and labels the device', () => {
    const { adapter, device } = ctx;
    expect(device.limits.maxStorageBufferBindingSize).toBe(adapter.limits.maxStorageBufferBindingSize);
    expect(device.limits.maxBufferSize).toBe(adapter.limits.maxBufferSize);
    expect(ctx.clamps).toHaveLength(2);
    expect(ctx.clamps[0]).toMatch(/^maxStorageBufferBindingSize: \d+ MiB of the 1048576 MiB asked for$/);
    expect(device.label).toBe('tessellab device');
    expect(ctx.timestamps).toBe(adapter.features.has('timestamp-query'));
    expect(device.features.has('timestamp-query')).toBe(ctx.timestamps);
  });

  it('explains a missing navigator.gpu, feature or limit', async () => {
    await expect(createGpu({ gpu: undefined })).rejects.toMatchObject({ problem: 'no-webgpu' });
    const missing = await createGpu({ gpu: gpuObject, requiredFeatures: ['no-such-feature' as GPUFeatureName] }).catch((e) => e);
    expect(missing).toBeInstanceOf(GpuUnavailableError);
    expect(missing.problem).toBe('missing-feature');
    expect(missing.message).toContain('no-such-feature');
    const limit = await createGpu({ gpu: gpuObject, minimumLimits: { maxStorageBufferBindingSize: 2 ** 52 } }).catch((e) => e);
    expect(limit.problem).toBe('limit');
    expect(limit.message).toContain('maxStorageBufferBindingSize');
  });

  it('reports a loss it did not cause, and not its own destroy()', async () => {
    const lost: string[] = [];
    const a = await createGpu({ gpu: gpuObject, onLost: (info) => lost.push(`a:${info.reason}`) });
    const b = await createGpu({ gpu: gpuObject, onLost: (info) => lost.push(`b:${info.reason}`) });
    a.destroy();
    b.device.destroy(); // as if the GPU went away under us
    await Promise.all([a.device.lost, b.device.lost]);
    await new Promise((r) => setTimeout(r, 0));
    expect(lost).toEqual(['b:destroyed']);
  });
});

describe('renderer', () => {
  it('draws the mesh, the backdrop, the wireframe and the cage without validation errors', async () => {
    const device = ctx.device;
    device.pushErrorScope('validation');
    const renderer = Renderer.create(device, { colorFormat: FORMAT, timestamps: ctx.timestamps, shadowMapSize: 512 });
    const mesh = uploadCageMesh(device, cube);
    const lines = uploadCageLines(device, cube);
    renderer.setBounds(boundsOf(cube.positions));

    const empty = await draw(renderer, { wireframe: true, cage: true });
    renderer.setMesh(mesh);
    renderer.setCage(lines);
    const plain = await draw(renderer, { wireframe: false, cage: false });
    const wired = await draw(renderer, { wireframe: true, cage: false });
    const caged = await draw(renderer, { wireframe: false, cage: true });
    const timings = await renderer.readTimings();
    expect(await device.popErrorScope()).toBeNull();

    // Nothing to draw: the backdrop (dark) everywhere, and the ground.
    expect(luma(pixel(empty, W / 2, H / 2))).toBeLessThan(90);
    // The model fills the middle, lit: brighter than the backdrop in the corner.
    const centre = pixel(plain, W / 2, H / 2);
    const corner = pixel(plain, 2, 2);
    expect(centre[3]).toBe(255);
    expect(luma(centre)).toBeGreaterThan(luma(corner) + 40);
    expect(pixel(plain, 2, 2)).toEqual(pixel(empty, 2, 2));
    // The overlays change the picture, and only where lines are.
    const wireDiff = differing(plain, wired);
    expect(wireDiff).toBeGreaterThan(50);
    expect(wireDiff).toBeLessThan(W * H * 0.5);
    expect(differing(plain, caged)).toBeGreaterThan(50);
    // Deterministic: the same frame twice is the same picture.
    expect(differing(plain, await draw(renderer, { wireframe: false, cage: false }))).toBe(0);

    if (ctx.timestamps) {
      expect(Object.keys(timings).sort()).toEqual(['lit', 'shadow']);
      for (const ms of Object.values(timings)) expect(ms).toBeGreaterThanOrEqual(0);
    } else {
      expect(timings).toEqual({});
    }
    renderer.destroy();
    destroyMesh(mesh);
    lines.vertices.destroy();
  });

  it('tints the surface by patch kind only with patch colours on and kinds given', async () => {
    const device = ctx.device;
    device.pushErrorScope('validation');
    const renderer = Renderer.create(device, { colorFormat: FORMAT, shadowMapSize: 256 });
    const mesh = uploadCageMesh(device, cube);
    renderer.setBounds(boundsOf(cube.positions));
    renderer.setMesh(mesh);
    const plain = await draw(renderer, { wireframe: false, cage: false });
    // No kinds: patch colours on changes nothing.
    expect(differing(plain, await draw(renderer, { wireframe: false, cage: false, patchColours: true }))).toBe(0);
    // Every triangle a crease patch (yellow), then every one regular (green).
    const triangles = 12;
    renderer.setPatchKinds(new Uint8Array(triangles).fill(3));
    expect(differing(plain, await draw(renderer, { wireframe: false, cage: false }))).toBe(0);
    const crease = await draw(renderer, { wireframe: false, cage: false, patchColours: true });
    renderer.setPatchKinds(new Uint8Array(triangles).fill(0));
    const regular = await draw(renderer, { wireframe: false, cage: false, patchColours: true });
    expect(await device.popErrorScope()).toBeNull();
    const c = pixel(crease, W / 2, H / 2);
    const r = pixel(regular, W / 2, H / 2);
    expect(c[0]).toBeGreaterThan(c[2] + 20); // yellow: red over blue
    expect(r[1]).toBeGreaterThan(r[0]); // green
    expect(r[1]).toBeGreaterThan(r[2]);
    // The backdrop is untouched.
    expect(pixel(crease, 2, 2)).toEqual(pixel(plain, 2, 2));
    renderer.destroy();
    destroyMesh(mesh);
  });

  it("follows the mesh's GPU-written draw args (indirect): zero triangles draw nothing", async () => {
    const device = ctx.device;
    device.pushErrorScope('validation');
    const renderer = Renderer.create(device, { colorFormat: FORMAT, shadowMapSize: 256 });
    const mesh = uploadCageMesh(device, cube);
    renderer.setBounds(boundsOf(cube.positions));
    const empty = await draw(renderer, { wireframe: true, cage: false });
    renderer.setMesh(mesh);
    device.queue.writeBuffer(mesh.drawArgs, 0, new Uint32Array([0, 1, 0, 0, 0]));
    const none = await draw(renderer, { wireframe: true, cage: false });
    device.queue.writeBuffer(mesh.drawArgs, 0, new Uint32Array([6, 1, 0, 0, 0])); // the first face only
    const one = await draw(renderer, { wireframe: true, cage: false });
    expect(await device.popErrorScope()).toBeNull();
    expect(differing(empty, none)).toBe(0);
    expect(differing(none, one)).toBeGreaterThan(0);
    renderer.destroy();
    destroyMesh(mesh);
  });
});
