/**
 * Adapter and device setup. DOM-free: the page passes `navigator.gpu`, the Node tests pass
 * dawn.node's GPU object.
 *
 * The tessellator stores the whole output mesh in a few large buffers (the talk's 16M-vertex
 * cap is ~700 MB), more than the device defaults (128 MiB per storage binding, 256 MiB per
 * buffer). The page says how much it would like (`wantedLimits`); we request that much where the
 * adapter has it, and otherwise what the adapter has, and list each such clamp in `clamps` so the
 * page can tell the user (its output buffers then shrink to fit: factors.ts outputCapacity).
 *
 * Limits the pipeline cannot run without (`minimumLimits`, PIPELINE_LIMITS) are requested as
 * they are, or the device is refused with a message naming them: a WebGPU compatibility-mode
 * adapter (OpenGL ES / D3D11 class) defaults to 128 invocations per workgroup and no storage
 * buffers in the vertex stage, though it may offer more when asked.
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

export type LimitName =
  | 'maxStorageBufferBindingSize'
  | 'maxBufferSize'
  | 'maxStorageBuffersPerShaderStage'
  | 'maxStorageBuffersInVertexStage'
  | 'maxComputeWorkgroupStorageSize'
  | 'maxComputeInvocationsPerWorkgroup'
  | 'maxComputeWorkgroupSizeX';

/**
 * What the demo's passes need beyond WebGPU compatibility mode's defaults: nothing. Every compute
 * pass fits compat's 128 invocations (wgsl/tess/scan.wgsl runs 128 threads), and the tessellate, shadow
 * and lit passes read no storage buffers in the vertex stage (compat: 0 by default).
 * tests/gpu/device/limits.node.test.ts runs the whole pipeline on a device with compatibility mode's own limits.
 */
export const PIPELINE_LIMITS: Partial<Record<LimitName, number>> = {};

/**
 * What the demo asks for where the adapter has it, and works without (GpuContext.clamps says what
 * was cut): storage buffers in the vertex stage, of which compatibility mode gives none by
 * default. The wireframe, the patch colours and the heat maps read per-vertex data from storage (2:
 * src/gpu/render/renderer.ts vertexStorage); the instanced tessellator evaluates its surface from it (up
 * to 6: src/gpu/instanced/levels.ts). Core WebGPU gives 8.
 */
export const OPTIONAL_LIMITS: Partial<Record<LimitName, number>> = {
  maxStorageBuffersInVertexStage: 8,
};

export interface DeviceOptions {
  /** `navigator.gpu`, or dawn.node's GPU object. */
  gpu: GPU | undefined;
  /** Features the app cannot run without (none today: the demo needs vanilla WebGPU). */
  requiredFeatures?: GPUFeatureName[];
  /** Smallest acceptable values of limits (checked against the adapter, then requested).
   * PIPELINE_LIMITS are always among them. A limit the adapter does not know (e.g.
   * maxStorageBuffersInVertexStage, which only implementations with compatibility mode have)
   * is not restricted there, and is not requested. */
  minimumLimits?: Partial<Record<LimitName, number>>;
  /** Limits the app would like (e.g. buffer sizes for the output it was asked for): requested up
   * to what the adapter has; where it has less, the clamp is listed in GpuContext.clamps. */
  wantedLimits?: Partial<Record<LimitName, number>>;
  /** 'compatibility' asks for a compatibility-mode adapter (where the implementation has one);
   * without it, and when no core adapter is available, the compatibility one is tried too. */
  featureLevel?: 'core' | 'compatibility';
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
  /** Wanted limits the adapter could not give, one sentence each ("maxBufferSize: 256 MiB of
   * the 768 MiB asked for"): the page says so. Empty when everything wanted was granted. */
  clamps: string[];
  /** Whether the device runs with WebGPU's compatibility-mode restrictions. */
  compatibility: boolean;
  /** Destroy the device without reporting a loss. */
  destroy(): void;
}

export async function createGpu(options: DeviceOptions): Promise<GpuContext> {
  const { gpu } = options;
  if (!gpu) {
    throw new GpuUnavailableError('no-webgpu', 'navigator.gpu is not defined: this browser does not support WebGPU, or it is turned off.');
  }
  const powerPreference = options.powerPreference ?? 'high-performance';
  // A device that only has compatibility mode (OpenGL ES, D3D11) gives no core adapter: ask for
  // a compatibility one then (implementations without the option ignore featureLevel).
  const adapter =
    (await gpu.requestAdapter({ powerPreference, featureLevel: options.featureLevel ?? 'core' })) ??
    (options.featureLevel === 'compatibility' ? null : await gpu.requestAdapter({ powerPreference, featureLevel: 'compatibility' }));
  if (!adapter) {
    throw new GpuUnavailableError(
      'no-adapter',
      'requestAdapter() returned null: WebGPU is supported, but no suitable GPU adapter is available (it may be blocklisted).',
    );
  }

  const missing = (options.requiredFeatures ?? []).filter((f) => !adapter.features.has(f));
  if (missing.length) {
    throw new GpuUnavailableError(
      'missing-feature',
      `This GPU lacks the WebGPU feature${missing.length > 1 ? 's' : ''} ${missing.join(', ')}.`,
    );
  }
  const { requiredLimits, clamps, short } = planLimits(
    adapter.limits,
    { ...PIPELINE_LIMITS, ...options.minimumLimits },
    { ...OPTIONAL_LIMITS, ...options.wantedLimits },
  );
  if (short.length) {
    throw new GpuUnavailableError('limit', `This GPU's limits are below what the demo needs: ${short.join('; ')}.`);
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
    clamps,
    // Without core-features-and-limits (a feature that core devices always have), compatibility
    // mode's restrictions apply; implementations that predate the feature have no such mode.
    compatibility: isCompatibilityDevice(device),
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

/** Whether `device` has WebGPU compatibility mode's restrictions. */
export function isCompatibilityDevice(device: GPUDevice): boolean {
  return hasCoreFeatureName(device) && !device.features.has('core-features-and-limits');
}

/** Implementations that know compatibility mode list core-features-and-limits on core devices
 * and expose maxStorageBuffersInVertexStage; older ones have neither (and are all core). */
function hasCoreFeatureName(device: GPUDevice): boolean {
  return 'maxStorageBuffersInVertexStage' in device.limits;
}

function formatLimit(name: string, value: number): string {
  return /Size$/.test(name) && value >= 2 ** 20 ? `${Math.round(value / 2 ** 20)} MiB` : String(value);
}

/**
 * The limits to request of an adapter: every minimum as it is (`short` lists those the adapter
 * lacks), every wanted value up to what the adapter has (`clamps` lists those cut). Limits the
 * adapter does not report are skipped: requesting an unknown limit fails device creation. Pure,
 * for tests/gpu/device/device-limits.test.ts.
 */
export function planLimits(
  adapterLimits: GPUSupportedLimits | Record<string, number | undefined>,
  minimum: Partial<Record<LimitName, number>>,
  wanted: Partial<Record<LimitName, number>>,
): { requiredLimits: Record<string, number>; clamps: string[]; short: string[] } {
  const has = (name: string) => (adapterLimits as Record<string, number | undefined>)[name];
  const requiredLimits: Record<string, number> = {};
  const clamps: string[] = [];
  const short: string[] = [];
  for (const [name, want] of Object.entries(wanted) as [LimitName, number][]) {
    const max = has(name);
    if (max === undefined) continue;
    requiredLimits[name] = Math.min(want, max);
    if (max < want) clamps.push(`${name}: ${formatLimit(name, max)} of the ${formatLimit(name, want)} asked for`);
  }
  for (const [name, min] of Object.entries(minimum) as [LimitName, number][]) {
    const max = has(name);
    if (max === undefined) continue;
    if (max < min) short.push(`${name} is ${max}, the demo needs ${min}`);
    else requiredLimits[name] = Math.max(requiredLimits[name] ?? 0, min);
  }
  return { requiredLimits, clamps, short };
}
