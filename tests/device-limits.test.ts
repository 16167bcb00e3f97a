/**
 * Device creation against adapters with small limits, without a GPU (src/gpu/device.ts): wanted
 * limits are requested up to what the adapter has and every cut is reported; the pipeline's own
 * minimums (PIPELINE_LIMITS) are requested as they are, or the device is refused with a message
 * naming each limit that falls short (a compatibility-mode adapter as the specification sets it).
 */
import { describe, expect, it } from 'vitest';
import { createGpu, GpuUnavailableError, PIPELINE_LIMITS, planLimits } from '../src/gpu/device.ts';

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
    expect(planLimits(CORE, PIPELINE_LIMITS, {}).short).toEqual([]);
    expect(planLimits(CORE, PIPELINE_LIMITS, {}).requiredLimits).toMatchObject(PIPELINE_LIMITS);
    // Compute fits compatibility mode's 128 invocations (wgsl/scan.wgsl runs 128 threads); the
    // vertex-stage storage buffers are what is left.
    expect(planLimits(COMPAT, PIPELINE_LIMITS, {}).short).toEqual(['maxStorageBuffersInVertexStage is 0, the demo needs 2']);
  });

  it('skips limits the adapter does not know (implementations without compatibility mode)', () => {
    const { maxStorageBuffersInVertexStage: _, ...older } = CORE;
    const p = planLimits(older, PIPELINE_LIMITS, {});
    expect(p.short).toEqual([]);
    expect('maxStorageBuffersInVertexStage' in p.requiredLimits).toBe(false);
  });
});

describe('createGpu on small adapters', () => {
  it('refuses a compatibility-mode adapter with the specification’s limits, naming them', async () => {
    const { gpu, requested } = fakeGpu(COMPAT);
    const e = await createGpu({ gpu }).catch((x) => x);
    expect(e).toBeInstanceOf(GpuUnavailableError);
    expect(e.problem).toBe('limit');
    expect(e.message).toContain('maxStorageBuffersInVertexStage is 0, the demo needs 2');
    expect(requested).toEqual([]);
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
