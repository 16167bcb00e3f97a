/** A GPUDevice from navigator.gpu (browser) or Dawn's `webgpu` package (Node), one per file. */
let pending: Promise<GPUDevice> | undefined;
// Dawn's instance must outlive its devices: if the object from create() is garbage-collected
// while a device is in use, the process dies in a mutex (SwiftShader or any other adapter).
let instance: GPU | undefined;

export function getDevice(): Promise<GPUDevice> {
  pending ??= (async () => {
    let gpu: GPU | undefined = (globalThis as { navigator?: { gpu?: GPU } }).navigator?.gpu;
    if (!gpu) {
      const name = 'webgpu'; // indirection keeps Vite from bundling dawn.node for the browser
      const { create, globals } = await import(/* @vite-ignore */ name);
      Object.assign(globalThis, globals);
      gpu = instance = create([]) as GPU;
    }
    const adapter = await gpu.requestAdapter();
    if (!adapter) throw new Error('no WebGPU adapter (is VK_ICD_FILENAMES pointing at SwiftShader?)');
    const device = await adapter.requestDevice({
      requiredFeatures: adapter.features.has('timestamp-query') ? ['timestamp-query'] : [],
      requiredLimits: {
        maxStorageBufferBindingSize: adapter.limits.maxStorageBufferBindingSize,
        maxBufferSize: adapter.limits.maxBufferSize,
      },
    });
    device.addEventListener('uncapturederror', (e) => console.error('WebGPU error:', (e as GPUUncapturedErrorEvent).error.message));
    return device;
  })();
  return pending;
}

export async function releaseDevice(): Promise<void> {
  if (pending) (await pending).destroy();
  pending = undefined;
  if (instance) instance = undefined;
}
