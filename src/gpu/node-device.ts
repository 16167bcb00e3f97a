/**
 * A GPUDevice in plain Node through Dawn (the `webgpu` npm package), for the headless CLI and
 * the benchmark. With no usable Vulkan driver, it falls back to the SwiftShader ICD that the
 * Debian `chromium` package ships (when the process is started that way: see adapterEnv).
 */
import { existsSync } from 'node:fs';

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
  const device = await adapter.requestDevice({
    label: 'tessellab headless',
    requiredFeatures: adapter.features.has('timestamp-query') ? ['timestamp-query'] : [],
    requiredLimits: {
      maxStorageBufferBindingSize: adapter.limits.maxStorageBufferBindingSize,
      maxBufferSize: adapter.limits.maxBufferSize,
    },
  });
  const info = adapter.info;
  return { device, adapterName: [info.vendor, info.architecture, info.device, info.description].filter(Boolean).join(' ') || 'unknown adapter' };
}
