/**
 * The contract's generated WGSL through a real WGSL compiler (Tint in Dawn, or the browser's):
 * the GPU reads the scene uniforms that TypeScript wrote and copies every float back; it runs the
 * generated bit getters and packers on words TypeScript packed; it reads the shared constants.
 * Exact comparisons: nothing here is computed, only moved.
 */
import { afterAll, describe, expect, it } from 'vitest';
import { wgslPrefix, type BitWord } from '../../../src/gpu/contract/define.ts';
import { constantsWgsl, SHARED_CONSTANTS } from '../../../src/gpu/contract/constants.ts';
import { ACC_TRI_CORNERS, ACC_TRI_WORD, BARY_WORD, OWNER_WORD, PATTERN_FRAME_WORD } from '../../../src/gpu/contract/tess.ts';
import { SCENE_UNIFORMS } from '../../../src/gpu/contract/render.ts';
import { ACC_SECTOR_WORD } from '../../../src/gpu/contract/acc.ts';
import { passBindings, tessellatorPasses } from '../../../src/gpu/tess/passes.ts';
import { getDevice, releaseDevice } from '../../support/gpu-device.ts';

afterAll(() => releaseDevice());

/** Run `main` (one thread) with a uniform or storage input at binding 0 and read `out` (binding 1). */
async function run(code: string, input: { uniform?: ArrayBuffer; storage?: Uint32Array }, outWords: number): Promise<Uint32Array> {
  const device = await getDevice();
  device.pushErrorScope('validation');
  const inBytes = input.uniform ?? input.storage!.buffer;
  const inBuf = device.createBuffer({
    label: 'contract test input',
    size: Math.max(16, inBytes.byteLength),
    usage: (input.uniform ? GPUBufferUsage.UNIFORM : GPUBufferUsage.STORAGE) | GPUBufferUsage.COPY_DST,
  });
  device.queue.writeBuffer(inBuf, 0, inBytes);
  const out = device.createBuffer({
    label: 'contract test output',
    size: 4 * outWords,
    usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC,
  });
  const read = device.createBuffer({
    label: 'contract test readback',
    size: 4 * outWords,
    usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
  });
  const module = device.createShaderModule({ label: 'contract test shader', code });
  const pipeline = device.createComputePipeline({
    label: 'contract test pipeline',
    layout: 'auto',
    compute: { module, entryPoint: 'main' },
  });
  const bindGroup = device.createBindGroup({
    label: 'contract test bind group',
    layout: pipeline.getBindGroupLayout(0),
    entries: [
      { binding: 0, resource: { buffer: inBuf } },
      { binding: 1, resource: { buffer: out } },
    ],
  });
  const encoder = device.createCommandEncoder({ label: 'contract test' });
  const pass = encoder.beginComputePass({ label: 'contract test pass' });
  pass.setPipeline(pipeline);
  pass.setBindGroup(0, bindGroup);
  pass.dispatchWorkgroups(1);
  pass.end();
  encoder.copyBufferToBuffer(out, 0, read, 0, 4 * outWords);
  device.queue.submit([encoder.finish()]);
  await read.mapAsync(GPUMapMode.READ);
  const words = new Uint32Array(read.getMappedRange().slice(0));
  read.unmap();
  const error = await device.popErrorScope();
  for (const b of [inBuf, out, read]) b.destroy();
  expect(error?.message ?? null).toBeNull();
  return words;
}

describe('generated WGSL on the GPU', () => {
  it('SceneUniforms: every float TypeScript wrote is where the shader reads that field', async () => {
    const fields = Object.keys(SCENE_UNIFORMS.offset) as (keyof typeof SCENE_UNIFORMS.offset)[];
    const sizes: Record<string, number> = {};
    const values: Record<string, number[]> = {};
    const copies: string[] = [];
    let next = 1;
    let at = 0;
    for (const f of fields) {
      // mat4x4 fields are 16 floats (column c, row r at 4c + r, as TypeScript writes column-major), vec4 are 4.
      const n = SCENE_UNIFORMS.wgsl.includes(`${f}: mat4x4<f32>`) ? 16 : 4;
      sizes[f] = n;
      values[f] = Array.from({ length: n }, () => next++ + 0.25);
      for (let i = 0; i < n; i++)
        copies.push(`  out[${at + i}u] = bitcast<u32>(scene.${f}${n === 16 ? `[${i >> 2}][${i & 3}]` : `[${i}]`});`);
      at += n;
    }
    const code = `${SCENE_UNIFORMS.wgsl}
@group(0) @binding(0) var<uniform> scene: SceneUniforms;
@group(0) @binding(1) var<storage, read_write> out: array<u32>;
@compute @workgroup_size(1) fn main() {
${copies.join('\n')}
}`;
    const bytes = new ArrayBuffer(SCENE_UNIFORMS.size);
    SCENE_UNIFORMS.write(new DataView(bytes), values);
    const got = new Float32Array((await run(code, { uniform: bytes }, at)).buffer);
    expect(Array.from(got)).toEqual(fields.flatMap((f) => values[f]));
  });

  const words = [PATTERN_FRAME_WORD, BARY_WORD, OWNER_WORD, ACC_SECTOR_WORD, ACC_TRI_WORD, ACC_TRI_CORNERS] as BitWord<string>[];
  for (const word of words) {
    it(`${word.name}: the WGSL getters read what TypeScript packed, and the WGSL packer packs what TypeScript does`, async () => {
      const names = Object.keys(word.fields);
      const prefix = wgslPrefix(word.name);
      // Deterministic spread of field values: 0, the maximum, and a walk in between.
      const samples = Array.from({ length: 32 }, (_, s) =>
        Object.fromEntries(
          names.map((f, k) => {
            const max = 2 ** word.fields[f][1] - 1;
            return [f, s === 0 ? 0 : s === 1 ? max : Math.floor((((s * 2654435761 + k * 40503) % 4294967296) / 4294967296) * (max + 1))];
          }),
        ),
      );
      const packed = Uint32Array.from(samples, (v) => word.pack(v));
      const per = names.length + 1;
      const code = `${word.wgsl}
@group(0) @binding(0) var<storage, read> words: array<u32>;
@group(0) @binding(1) var<storage, read_write> out: array<u32>;
@compute @workgroup_size(1) fn main() {
  for (var i = 0u; i < ${samples.length}u; i++) {
    let w = words[i];
${names.map((f, k) => `    out[i * ${per}u + ${k}u] = ${prefix}_${f}(w);`).join('\n')}
    out[i * ${per}u + ${names.length}u] = ${prefix}_pack(${names.map((f) => `${prefix}_${f}(w)`).join(', ')});
  }
}`;
      const got = await run(code, { storage: packed }, samples.length * per);
      samples.forEach((v, i) => {
        expect(Array.from(got.subarray(i * per, i * per + names.length))).toEqual(names.map((f) => v[f]));
        expect(got[i * per + names.length]).toBe(packed[i]);
      });
    });
  }

  it('the constants prelude compiles and holds the TypeScript values', async () => {
    const names = Object.keys(SHARED_CONSTANTS) as (keyof typeof SHARED_CONSTANTS)[];
    const code = `${constantsWgsl}
@group(0) @binding(0) var<storage, read> unused: array<u32>;
@group(0) @binding(1) var<storage, read_write> out: array<u32>;
@compute @workgroup_size(1) fn main() {
  out[0] = unused[0] * 0u;
${names.map((n, i) => `  out[${i + 1}u] = ${n};`).join('\n')}
}`;
    const got = await run(code, { storage: new Uint32Array(4) }, names.length + 1);
    expect(Array.from(got.subarray(1))).toEqual(names.map((n) => SHARED_CONSTANTS[n]));
  });
});

/**
 * Each pipeline's bindings against the contract's, as the WGSL compiler sees them: the pipeline
 * built on the contract's explicit layout must validate (every binding the entry point uses is
 * there, with its type and access), and the compiler's own 'auto' layout of the same entry point
 * must accept a bind group of exactly the contract's bindings (no binding more, none less).
 */
describe("the tessellator's pipelines bind what the contract says", () => {
  /** The validation errors (null: none) of building the pass on `entries` and binding them to its 'auto' layout. */
  async function check(label: string, code: string, entry: string, entries: GPUBindGroupLayoutEntry[]): Promise<string | null> {
    const device = await getDevice();
    device.pushErrorScope('validation');
    const module = device.createShaderModule({ label, code });
    const layout = device.createBindGroupLayout({ label, entries });
    device.createComputePipeline({
      label,
      layout: device.createPipelineLayout({ label, bindGroupLayouts: [layout] }),
      compute: { module, entryPoint: entry },
    });
    const explicit = await device.popErrorScope();
    device.pushErrorScope('validation');
    const auto = device.createComputePipeline({ label: `${label} (auto)`, layout: 'auto', compute: { module, entryPoint: entry } });
    const buffers = entries.map(() =>
      device.createBuffer({ label: `${label} binding`, size: 4096, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.STORAGE }),
    );
    device.createBindGroup({
      label,
      layout: auto.getBindGroupLayout(0),
      entries: entries.map((e, i) => ({ binding: e.binding, resource: { buffer: buffers[i] } })),
    });
    const bound = await device.popErrorScope();
    for (const b of buffers) b.destroy();
    return explicit?.message ?? bound?.message ?? null;
  }

  for (const surface of ['phong', 'catmull-clark'] as const) {
    it(`${surface}: every pass`, async () => {
      for (const pass of tessellatorPasses(surface))
        await check(`${surface} ${pass.name}`, pass.code, pass.entry, passBindings(pass).entries);
    }, 120_000);
  }

  it('and it would notice: a binding short, one more, or a storage buffer bound read-only', async () => {
    const scanDown = tessellatorPasses('phong').find((p) => p.name === 'scanDown')!;
    const { entries } = passBindings(scanDown);
    const run = (e: GPUBindGroupLayoutEntry[]) => check('scanDown (altered)', scanDown.code, scanDown.entry, e);
    expect(await run(entries.slice(0, -1))).not.toBeNull();
    expect(await run([...entries, { binding: 7, visibility: entries[0].visibility, buffer: { type: 'storage' } }])).not.toBeNull();
    expect(
      await run(entries.map((e) => (e.buffer?.type === 'storage' ? { ...e, buffer: { type: 'read-only-storage' } } : e))),
    ).not.toBeNull();
  });
});
