/**
 * Device creation against adapters with small limits, without a GPU (src/gpu/device/device.ts): wanted
 * limits are requested up to what the adapter has and every cut is reported; the pipeline's own
 * minimums (PIPELINE_LIMITS) are requested as they are, or the device is refused with a message
 * naming each limit that falls short (a compatibility-mode adapter as the specification sets it).
 */
import { describe, expect, it } from 'vitest';
import { createGpu, OPTIONAL_LIMITS, PIPELINE_LIMITS, planLimits } from '../../../src/gpu/device/device.ts';

/** WebGPU's default limits, and compatibility mode's where they are lower (the spec's table). */
const CORE = {
  maxStorageBufferBindingSize: 128 * 2 ** 20,
  maxBufferSize: 256 * 2 ** 20,
  maxStorageBuffersPerShaderStage: 8,
  maxStorageBuffersInVertexStage: 8,
  maxComputeInvocationsPerWorkgroup: 256,
  maxComputeWorkgroupSizeX: 256,
};
const COMPAT = { ...CORE, maxStorageBuffersInVertexStage: 0, maxComputeInvocationsPerWorkgroup: 128, maxComputeWorkgroupSizeX: 128 };

/** A GPU whose one adapter has `limits`, recording what requestDevice was asked for. */
function fakeGpu(limits: Record<string, number>, features: string[] = []) {
  const requested: GPUDeviceDescriptor[] = [];
  const adapter = {
    limits,
    features: new Set(features),
    info: { vendor: 'test', architecture: '', description: 'fake adapter' },
    async requestDevice(desc: GPUDeviceDescriptor) {
      requested.push(desc);
      return {
        label: desc.label,
        limits: { ...limits, ...desc.requiredLimits },
        features: new Set(['core-features-and-limits']),
        lost: new Promise(() => {}),
        addEventListener() {},
        destroy() {},
      };
    },
  };
  const gpu = { requestAdapter: async () => adapter } as unknown as GPU;
  return { gpu, requested };
}

describe('planLimits', () => {
  it('requests wanted limits up to the adapter’s, and lists the cuts', () => {
    const p = planLimits(CORE, {}, { maxStorageBufferBindingSize: 192 * 2 ** 20, maxBufferSize: 100 * 2 ** 20 });
    expect(p.requiredLimits).toEqual({ maxStorageBufferBindingSize: 128 * 2 ** 20, maxBufferSize: 100 * 2 ** 20 });
    expect(p.clamps).toEqual(['maxStorageBufferBindingSize: 128 MiB of the 192 MiB asked for']);
    expect(p.short).toEqual([]);
  });

  it('requests minimums as they are; names each one the adapter lacks', () => {
    const need = { maxComputeInvocationsPerWorkgroup: 256, maxStorageBuffersInVertexStage: 2 };
    expect(planLimits(CORE, need, {}).short).toEqual([]);
    expect(planLimits(CORE, need, {}).requiredLimits).toMatchObject(need);
    expect(planLimits(COMPAT, need, {}).short).toEqual([
      'maxComputeInvocationsPerWorkgroup is 128, the demo needs 256',
      'maxStorageBuffersInVertexStage is 0, the demo needs 2',
    ]);
    // The demo's own: nothing beyond compatibility mode's defaults.
    expect(PIPELINE_LIMITS).toEqual({});
    expect(planLimits(COMPAT, PIPELINE_LIMITS, {}).short).toEqual([]);
  });

  it('skips limits the adapter does not know (implementations without compatibility mode)', () => {
    const { maxStorageBuffersInVertexStage: _, ...older } = CORE;
    const p = planLimits(older, { maxStorageBuffersInVertexStage: 2 }, OPTIONAL_LIMITS);
    expect(p.short).toEqual([]);
    expect('maxStorageBuffersInVertexStage' in p.requiredLimits).toBe(false);
  });
});

describe('createGpu on small adapters', () => {
  it('takes a compatibility-mode adapter with the specification’s limits, and says what it cut', async () => {
    const { gpu, requested } = fakeGpu(COMPAT);
    const ctx = await createGpu({ gpu });
    expect(requested.length).toBe(1);
    expect(requested[0].requiredLimits).toMatchObject({ maxStorageBuffersInVertexStage: 0 });
    expect(ctx.clamps).toEqual(['maxStorageBuffersInVertexStage: 0 of the 8 asked for']);
  });

  it('on an adapter with default limits, asks for no more than it has and reports the clamp', async () => {
    const { gpu, requested } = fakeGpu(CORE);
    const ctx = await createGpu({ gpu, wantedLimits: { maxStorageBufferBindingSize: 12 * 16e6, maxBufferSize: 12 * 16e6 } });
    for (const [name, value] of Object.entries(requested[0].requiredLimits ?? {})) {
      expect(value, name).toBeLessThanOrEqual(CORE[name as keyof typeof CORE]);
    }
    expect(ctx.clamps).toEqual(['maxStorageBufferBindingSize: 128 MiB of the 183 MiB asked for']);
  });
});
