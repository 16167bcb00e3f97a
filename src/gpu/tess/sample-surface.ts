/**
 * Evaluate the tessellator's current surface (evalSurface of its surface module) at arbitrary
 * (cage triangle, barycentric) points on the GPU: for checks against the CPU reference and for
 * the headless CLI. Uses the tessellator's own buffers, so call it after an encode() has been
 * submitted (the uniforms and the patch build are then current).
 */
import commonWgsl from '../../../wgsl/tess/common.wgsl?raw';
import { surfaceScheme } from '../surface/registry.ts';
import { TESS_GROUP, TESS_INPUTS, TESS_SAMPLE_GROUP, type TessBinding } from '../contract/tess.ts';
import { tessPrelude } from '../contract/contract.ts';
import type { Tessellator } from './tessellator.ts';
import { readBuffer } from '../device/readback.ts';

// Its own bindings: TESS_SAMPLE_GROUP (samples, results), beside the tessellator's inputs.
const KERNEL = /* wgsl */ `
@compute @workgroup_size(WORKGROUP_SIZE)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
  let i = gid.x;
  if (i >= arrayLength(&samples) / 3u) { return; }
  let t = samples[3u * i];
  let w1 = samples[3u * i + 1u];
  let w2 = samples[3u * i + 2u];
  let s = evalSurface(t, vec3<u32>(ONE - w1 - w2, w1, w2));
  results[6u * i] = s.pos.x;
  results[6u * i + 1u] = s.pos.y;
  results[6u * i + 2u] = s.pos.z;
  results[6u * i + 3u] = s.normal.x;
  results[6u * i + 4u] = s.normal.y;
  results[6u * i + 5u] = s.normal.z;
}
`;

const pipelines = new WeakMap<GPUDevice, Map<string, GPUComputePipeline>>();

/** Bind group entries of a tessellator's own buffers, at their TESS_GROUP bindings (for a check's
 * kernel that reads them beside bindings of its own). */
export function tessInputEntries(tess: Tessellator, names: readonly TessBinding[]): GPUBindGroupEntry[] {
  const buffers: Partial<Record<TessBinding, GPUBuffer>> = {
    params: tess.paramsBuffer,
    staticBuf: tess.staticBuffer,
    cageBuf: tess.cageBuffer,
    work: tess.workBuffer,
  };
  return names.map((name) => {
    const buffer = buffers[name];
    if (!buffer) throw new Error(`tessInputEntries: ${name} is not one of the tessellator's inputs`);
    return { binding: TESS_GROUP.binding[name], resource: { buffer } };
  });
}

/** Samples: triangle t and fixed-point weights (w1, w2) of corners 1 and 2 (w0 = 65536 − w1 − w2). */
export async function sampleSurface(
  tess: Tessellator,
  samples: { t: number; w1: number; w2: number }[],
): Promise<{ pos: Float32Array; normal: Float32Array }> {
  const device = tess.device;
  let byKind = pipelines.get(device);
  if (!byKind) pipelines.set(device, (byKind = new Map()));
  let pipe = byKind.get(tess.surface);
  if (!pipe) {
    const surface = surfaceScheme(tess.surface).tessWgsl;
    const module = device.createShaderModule({
      label: 'surface samples',
      code: [tessPrelude(TESS_INPUTS), TESS_SAMPLE_GROUP.wgsl(), commonWgsl, surface, KERNEL].join('\n'),
    });
    pipe = device.createComputePipeline({ label: 'surface samples', layout: 'auto', compute: { module, entryPoint: 'main' } });
    byKind.set(tess.surface, pipe);
  }
  const n = samples.length;
  const words = new Uint32Array(3 * Math.max(n, 1));
  samples.forEach((s, i) => words.set([s.t, s.w1, s.w2], 3 * i));
  const input = device.createBuffer({ label: 'samples', size: words.byteLength, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST });
  device.queue.writeBuffer(input, 0, words);
  const output = device.createBuffer({
    label: 'sample results',
    size: 24 * Math.max(n, 1),
    usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC,
  });
  const group = device.createBindGroup({
    layout: pipe.getBindGroupLayout(0),
    entries: [
      ...tessInputEntries(tess, surfaceScheme(tess.surface).readsWork ? TESS_INPUTS : TESS_INPUTS.filter((b) => b !== 'work')),
      { binding: TESS_SAMPLE_GROUP.binding.samples, resource: { buffer: input } },
      { binding: TESS_SAMPLE_GROUP.binding.results, resource: { buffer: output } },
    ],
  });
  const enc = device.createCommandEncoder({ label: 'surface samples' });
  const cp = enc.beginComputePass();
  cp.setPipeline(pipe);
  cp.setBindGroup(0, group);
  cp.dispatchWorkgroups(Math.ceil(n / 64));
  cp.end();
  device.queue.submit([enc.finish()]);
  const f = new Float32Array(await readBuffer(device, output, 24 * n));
  input.destroy();
  output.destroy();
  const pos = new Float32Array(3 * n),
    normal = new Float32Array(3 * n);
  for (let i = 0; i < n; i++) {
    pos.set(f.subarray(6 * i, 6 * i + 3), 3 * i);
    normal.set(f.subarray(6 * i + 3, 6 * i + 6), 3 * i);
  }
  return { pos, normal };
}
