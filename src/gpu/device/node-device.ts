/**
 * A GPUDevice in plain Node through Dawn (the `webgpu` npm package), for the headless CLI and
 * the benchmark. With no usable Vulkan driver, it falls back to the SwiftShader ICD that the
 * Debian `chromium` package ships (when the process is started that way: see adapterEnv).
 */
import { existsSync } from 'node:fs';
import { PIPELINE_LIMITS, planLimits } from './device.ts';

export const SWIFTSHADER_ICD = '/usr/lib/chromium/vk_swiftshader_icd.json';

// Dawn's instances must outlive their devices: a collected instance kills the process.
const instances: unknown[] = [];

export async function createNodeDevice(dawnToggles: string[] = []): Promise<{ device: GPUDevice; adapterName: string }> {
  const name = 'webgpu';
  const { create, globals } = await import(/* @vite-ignore */ name);
  Object.assign(globalThis, globals);
  const gpu = create(dawnToggles) as GPU;
  instances.push(gpu);
  const adapter = await gpu.requestAdapter({ powerPreference: 'high-performance' });
  if (!adapter) {
    const hint = existsSync(SWIFTSHADER_ICD)
      ? `set VK_ICD_FILENAMES=${SWIFTSHADER_ICD} to use SwiftShader`
      : 'install a Vulkan driver, or the Debian chromium package for SwiftShader';
    throw new Error(`no WebGPU adapter: ${hint}`);
  }
  // The largest output buffers the adapter allows (the CLI's capacity option asks for them), and
  // the pipeline's own minimums (device.ts PIPELINE_LIMITS: a compatibility-mode adapter has
  // smaller defaults, and is refused with the limits it lacks).
  const { requiredLimits, short } = planLimits(adapter.limits, PIPELINE_LIMITS, {
    maxStorageBufferBindingSize: adapter.limits.maxStorageBufferBindingSize,
    maxBufferSize: adapter.limits.maxBufferSize,
  });
  if (short.length) throw new Error(`the WebGPU adapter's limits are below what the pipeline needs: ${short.join('; ')}`);
  const device = await adapter.requestDevice({
    label: 'tessellab headless',
    requiredFeatures: adapter.features.has('timestamp-query') ? ['timestamp-query'] : [],
    requiredLimits,
  });
  const info = adapter.info;
  return {
    device,
    adapterName: [info.vendor, info.architecture, info.device, info.description].filter(Boolean).join(' ') || 'unknown adapter',
  };
}
