/**
 * What the benchmarks share (bench/bench.ts, bench/instanced.ts, bench/talk.ts): one rebuild of
 * the compute tessellator timed by its GPU timestamps, the write-only kernel that bounds it, and
 * what the times mean on the adapter that measured them.
 */
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import type { Tessellator } from '../src/gpu/tess/tessellator.ts';
import type { PreparedMesh } from '../src/gpu/tess/prepare.ts';
import { headlessCamera, type HeadlessOptions } from '../src/gpu/tess/headless.ts';
import { readBuffer } from '../src/gpu/device/readback.ts';
import type { CatmullClarkData } from '../src/gpu/cc/build.ts';
import type { AccSurface as AccSurfaceData } from '../src/gpu/acc/surface.ts';

/** SwiftShader (a CPU rasteriser), where only ratios between timings mean anything. */
export const isSwiftShader = (adapterName: string): boolean => /swiftshader/i.test(adapterName);

/** What the times mean on the adapter that measured them. */
export function adapterNote(adapterName: string): string {
  return isSwiftShader(adapterName)
    ? "On SwiftShader (a CPU rasteriser) only these ratios mean anything; a real GPU's tables are in the section 'On a real GPU' (bench/gpu/)."
    : "Measured on a real GPU: the milliseconds are that GPU's.";
}

export interface Run {
  vertices: number;
  triangles: number;
  stages: Record<string, number>;
  total: number;
}

export function median(xs: number[]): number {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
}

export async function timeRebuild(
  device: GPUDevice,
  tess: Tessellator,
  mesh: PreparedMesh,
  o: HeadlessOptions,
  repeats: number,
  cc?: CatmullClarkData,
  acc?: AccSurfaceData,
): Promise<Run> {
  tess.setMesh(mesh, cc, acc);
  const samples: Record<string, number>[] = [];
  for (let i = 0; i < repeats + 1; i++) {
    const enc = device.createCommandEncoder({ label: 'bench rebuild' });
    tess.encode(enc, headlessCamera(mesh, o));
    device.queue.submit([enc.finish()]);
    // Wait for the GPU first: the timestamp read gives up after TIMING_MAP_DEADLINE_MS (the demo's
    // stats must not hang on it), and on SwiftShader imrod's rebuild alone runs longer than that.
    await device.queue.onSubmittedWorkDone();
    const t = await tess.readTimings();
    if (i > 0) samples.push(t); // the first run warms up
  }
  const counts = new Uint32Array(await readBuffer(device, tess.output.counts, 16));
  const stages: Record<string, number> = {};
  for (const k of Object.keys(samples[0] ?? {})) stages[k] = median(samples.map((s) => s[k]));
  return { vertices: counts[0], triangles: counts[1], stages, total: Object.values(stages).reduce((a, b) => a + b, 0) };
}

/** A kernel that only writes `bytes` bytes (u32 stores, fully coalesced): the write bound. */
export async function timeTrivialWrite(device: GPUDevice, bytes: number, repeats: number): Promise<number> {
  const words = Math.max(64, Math.ceil(bytes / 4));
  const buffer = device.createBuffer({ label: 'bench write target', size: 4 * words, usage: GPUBufferUsage.STORAGE });
  const module = device.createShaderModule({
    label: 'bench trivial write',
    code: `@group(0) @binding(0) var<storage, read_write> out: array<u32>;
      @compute @workgroup_size(256) fn main(@builtin(workgroup_id) w: vec3<u32>, @builtin(local_invocation_index) l: u32) {
        let i = (w.y * 65535u + w.x) * 256u + l;
        if (i < arrayLength(&out)) { out[i] = i; }
      }`,
  });
  const pipeline = device.createComputePipeline({ label: 'bench trivial write', layout: 'auto', compute: { module, entryPoint: 'main' } });
  const group = device.createBindGroup({ layout: pipeline.getBindGroupLayout(0), entries: [{ binding: 0, resource: { buffer } }] });
  const querySet = device.createQuerySet({ type: 'timestamp', count: 2 });
  const resolve = device.createBuffer({ size: 16, usage: GPUBufferUsage.QUERY_RESOLVE | GPUBufferUsage.COPY_SRC });
  const groups = Math.ceil(words / 256);
  const [gx, gy] = groups <= 65535 ? [groups, 1] : [65535, Math.ceil(groups / 65535)];
  const ms: number[] = [];
  for (let i = 0; i < repeats + 1; i++) {
    const enc = device.createCommandEncoder();
    const pass = enc.beginComputePass({ timestampWrites: { querySet, beginningOfPassWriteIndex: 0, endOfPassWriteIndex: 1 } });
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, group);
    pass.dispatchWorkgroups(gx, gy);
    pass.end();
    enc.resolveQuerySet(querySet, 0, 2, resolve, 0);
    device.queue.submit([enc.finish()]);
    const t = new BigUint64Array(await readBuffer(device, resolve, 16));
    if (i > 0) ms.push(Number(t[1] - t[0]) / 1e6);
  }
  buffer.destroy();
  querySet.destroy();
  resolve.destroy();
  return median(ms);
}

/**
 * Writes `section` (starting with its `## title`) into `outFile`: in place when the section is
 * there (a rerun must not move it); else before the real-GPU part, so the SwiftShader tables stay
 * together; else at the end. The benchmarks that keep their own section of BENCHMARKS.md use it.
 */
export function writeSection(outFile: string, title: string, section: string): void {
  const doc = existsSync(outFile) ? readFileSync(outFile, 'utf8') : '# Benchmarks\n';
  const parts = doc.split(/^(?=## )/m);
  const own = parts.findIndex((p) => p.startsWith(title));
  const gpu = parts.findIndex((p) => /^## (Reading the real-GPU|On a real GPU)/.test(p));
  if (own >= 0) parts[own] = `${section}\n`;
  else if (gpu >= 0) parts.splice(gpu, 0, `${section}\n`);
  else parts.push(`${parts.pop()?.trimEnd() ?? ''}\n\n${section}`);
  writeFileSync(outFile, `${parts.join('').trimEnd()}\n`);
  console.log(`\nwritten to ${outFile}`);
}
