/**
 * wgsl/cc/crease-basis.wgsl (f32) against its f64 twin src/subdiv/crease-basis.ts (itself tested
 * against exact refinement in tests/subdiv/crease-basis.test.ts): one tiny compute pass evaluates
 * creaseRowWeights over a grid of (σ, u), both read as the same f32 inputs, and every one of
 * the 8 weights is compared. Tolerance: 1e-6 absolute per weight; all weights are bounded by
 * 2 in magnitude, so this is a few f32 ulps of the largest ones.
 */
import { afterAll, describe, expect, it } from 'vitest';
import { getDevice, releaseDevice } from '../../support/gpu-device.ts';
import { readBuffer } from '../../../src/gpu/device/readback.ts';
import { creaseRowWeights } from '../../../src/subdiv/crease-basis.ts';
import creaseWgsl from '../../../wgsl/cc/crease-basis.wgsl?raw';

afterAll(() => releaseDevice());

const TOL = 1e-6;

const kernel = /* wgsl */ `
${creaseWgsl}
// Input: (σ, u) pairs. Output: per pair value.xyzw then du.xyzw.
@group(0) @binding(0) var<storage, read> inputs: array<vec2<f32>>;
@group(0) @binding(1) var<storage, read_write> outputs: array<vec4<f32>>;
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
  let i = id.x;
  if (i >= arrayLength(&inputs)) { return; }
  let w = creaseRowWeights(inputs[i].x, inputs[i].y);
  outputs[2u * i] = w.value;
  outputs[2u * i + 1u] = w.du;
}
`;

describe('crease row weights in WGSL', () => {
  it('equal the f64 weights at the same f32 (σ, u) within 1e-6 per weight', async () => {
    const sigmas = [-1, 0, 0.25, 0.5, 1, 1.5, 2, 2.3, 2.7, 3.7, 5, 8.5, 9, 9.75, 10, 12];
    const us: number[] = [];
    for (let x = 0; x <= 128; x++) us.push(x / 128);
    // Near the crease and round every level breakpoint 2^-k that σ < 10 can reach.
    us.push(1e-6, 3e-5, 1e-3);
    for (let k = 1; k <= 10; k++) us.push(2 ** -k * 0.999, 2 ** -k * 1.001);
    const pairs = new Float32Array(2 * sigmas.length * us.length);
    let n = 0;
    for (const s of sigmas)
      for (const u of us) {
        pairs[2 * n] = s;
        pairs[2 * n + 1] = u;
        n++;
      }

    const device = await getDevice();
    const module = device.createShaderModule({ label: 'crease-basis test', code: kernel });
    const info = await module.getCompilationInfo();
    expect(info.messages.filter((m) => m.type === 'error').map((m) => m.message)).toEqual([]);
    const pipeline = device.createComputePipeline({ label: 'crease-basis test', layout: 'auto', compute: { module, entryPoint: 'main' } });
    const input = device.createBuffer({
      label: 'crease-basis inputs',
      size: pairs.byteLength,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST,
    });
    const output = device.createBuffer({
      label: 'crease-basis outputs',
      size: 32 * n,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC,
    });
    device.queue.writeBuffer(input, 0, pairs);
    const bind = device.createBindGroup({
      label: 'crease-basis test',
      layout: pipeline.getBindGroupLayout(0),
      entries: [
        { binding: 0, resource: { buffer: input } },
        { binding: 1, resource: { buffer: output } },
      ],
    });
    const enc = device.createCommandEncoder({ label: 'crease-basis test' });
    const pass = enc.beginComputePass({ label: 'crease-basis test' });
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, bind);
    pass.dispatchWorkgroups(Math.ceil(n / 64));
    pass.end();
    device.queue.submit([enc.finish()]);
    const got = new Float32Array(await readBuffer(device, output, 32 * n));
    input.destroy();
    output.destroy();

    let worstValue = 0,
      worstDu = 0,
      where = '';
    for (let i = 0; i < n; i++) {
      const w = creaseRowWeights(pairs[2 * i], pairs[2 * i + 1]);
      for (let j = 0; j < 4; j++) {
        const dv = Math.abs(got[8 * i + j] - w.value[j]),
          dd = Math.abs(got[8 * i + 4 + j] - w.du[j]);
        if (!(dv <= worstValue)) {
          worstValue = dv;
          if (dv > TOL) where = `σ ${pairs[2 * i]} u ${pairs[2 * i + 1]} value ${j}`;
        }
        if (!(dd <= worstDu)) {
          worstDu = dd;
          if (dd > TOL) where = `σ ${pairs[2 * i]} u ${pairs[2 * i + 1]} du ${j}`;
        }
      }
    }
    console.log(`crease weights, ${n} (σ, u) pairs: max |Δ value| ${worstValue.toExponential(2)}, max |Δ du| ${worstDu.toExponential(2)}`);
    expect(worstValue, where).toBeLessThanOrEqual(TOL);
    expect(worstDu, where).toBeLessThanOrEqual(TOL);
  });
});
