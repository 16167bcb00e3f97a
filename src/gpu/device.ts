/**
 * Adapter and device setup. DOM-free: the page passes `navigator.gpu`, the Node tests pass
 * dawn.node's GPU object.
 *
 * The tessellator stores the whole output mesh in a few large buffers (the talk's 16M-vertex
 * cap is ~700 MB), so we ask for the largest buffer limits the adapter allows: the device
 * defaults are only 128 MiB per storage binding and 256 MiB per buffer, whatever the GPU.
 */

export type GpuProblem = 'no-webgpu' | 'no-adapter' | 'missing-feature' | 'limit' | 'device-failed';

/** Why there is no usable device: the page turns `problem` into the right message. */
export class GpuUnavailableError extends Error {
  readonly problem: GpuProblem;
  constructor(problem: GpuProblem, message: string) {
    super(message);
    this.name = 'GpuUnavailableError';
    this.problem = problem;
  }
}

export type LimitName = 'maxStorageBufferBindingSize' | 'maxBufferSize' | 'maxStorageBuffersPerShaderStage' | 'maxComputeWorkgroupStorageSize' | 'maxComputeInvocationsPerWorkgroup';

export interface DeviceOptions {
  /** `navigator.gpu`, or dawn.node's GPU object. */
  gpu: GPU | undefined;
  /** Features the app cannot run without (none today: the demo needs vanilla WebGPU). */
  requiredFeatures?: GPUFeatureName[];
  /** Smallest acceptable values of limits (checked against the adapter, then requested). */
  minimumLimits?: Partial<Record<LimitName, number>>;
  /** Called once when the device is lost for any reason other than our own `destroy()`. */
  onLost?: (info: GPUDeviceLostInfo) => void;
  /** Validation and out-of-memory errors nobody caught with an error scope. */
  onUncapturedError?: (error: GPUError) => void;
  powerPreference?: GPUPowerPreference;
}

export interface GpuContext {
  adapter: GPUAdapter;
  device: GPUDevice;
  /** 'timestamp-query' was available and is enabled. */
  timestamps: boolean;
  /** "vendor / architecture / description", for the stats panel and bug reports. */
  adapterName: string;
  /** Destroy the device without reporting a loss. */
  destroy(): void;
}

/** Limits raised to the adapter's maximum: everything that bounds how big the output mesh may be. */
const RAISED_LIMITS: LimitName[] = ['maxStorageBufferBindingSize', 'maxBufferSize', 'maxStorageBuffersPerShaderStage'];

export async function createGpu(options: DeviceOptions): Promise<GpuContext> {
  const { gpu } = options;
  if (!gpu) {
    throw new GpuUnavailableError('no-webgpu', 'navigator.gpu is not defined: this browser does not support WebGPU, or it is turned off.');
  }
  const adapter = await gpu.requestAdapter({ powerPreference: options.powerPreference ?? 'high-performance' });
  if (!adapter) {
    throw new GpuUnavailableError('no-adapter', 'requestAdapter() returned null: WebGPU is supported, but no suitable GPU adapter is available (it may be blocklisted).');
  }

  const missing = (options.requiredFeatures ?? []).filter((f) => !adapter.features.has(f));
  if (missing.length) {
    throw new GpuUnavailableError('missing-feature', `This GPU lacks the WebGPU feature${missing.length > 1 ? 's' : ''} ${missing.join(', ')}.`);
  }
  for (const [name, min] of Object.entries(options.minimumLimits ?? {}) as [LimitName, number][]) {
    const has = adapter.limits[name];
    if (has < min) {
      throw new GpuUnavailableError('limit', `This GPU's ${name} is ${has}; the demo needs at least ${min}.`);
    }
  }

  const requiredLimits: Record<string, number> = {};
  for (const name of RAISED_LIMITS) requiredLimits[name] = adapter.limits[name];
  for (const [name, min] of Object.entries(options.minimumLimits ?? {})) {
    requiredLimits[name] = Math.max(requiredLimits[name] ?? 0, min);
  }
  // Timestamps are optional: with them the stats show per-pass GPU time, without them they say so.
  const timestamps = adapter.features.has('timestamp-query');
  const requiredFeatures: GPUFeatureName[] = [...(options.requiredFeatures ?? [])];
  if (timestamps) requiredFeatures.push('timestamp-query');

  let device: GPUDevice;
  try {
    device = await adapter.requestDevice({ label: 'tessellab device', requiredFeatures, requiredLimits });
  } catch (e) {
    throw new GpuUnavailableError('device-failed', `requestDevice() failed: ${(e as Error)?.message ?? String(e)}`);
  }

  let destroyedByUs = false;
  device.lost.then((info) => {
    if (!destroyedByUs) options.onLost?.(info);
  });
  if (options.onUncapturedError) {
    const report = options.onUncapturedError;
    device.addEventListener('uncapturederror', (ev) => report((ev as GPUUncapturedErrorEvent).error));
  }

  return {
    adapter,
    device,
    timestamps,
    adapterName: describeAdapter(adapter),
    destroy() {
      destroyedByUs = true;
      device.destroy();
    },
  };
}

function describeAdapter(adapter: GPUAdapter): string {
  const info = adapter.info;
  if (!info) return 'unknown adapter';
  return [info.vendor, info.architecture, info.description].filter((s) => s?.length).join(' / ') || 'unknown adapter';
}
