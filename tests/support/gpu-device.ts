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

import { mat4 } from 'gl-matrix';
import type { PreparedMesh } from '../../src/gpu/tess/prepare.ts';
import type { FactorParams } from '../../src/gpu/contract/tessellated-mesh.ts';

/** A test camera looking at the model's centre from eyeDistance (fixed mode when `fixed` is given). */
export function testCamera(mesh: PreparedMesh, eyeDistance: number, fixed?: number, lodScale = 1): FactorParams {
  const c = [0, 1, 2].map((i) => (mesh.bboxMin[i] + mesh.bboxMax[i]) / 2) as [number, number, number];
  const eye: [number, number, number] = [c[0] + 0.3 * eyeDistance, c[1] + 0.5 * eyeDistance, c[2] + eyeDistance];
  const view = mat4.lookAt(mat4.create(), eye, c, [0, 1, 0]);
  const proj = mat4.perspectiveZO(mat4.create(), Math.PI / 4, 1, 0.01, 100);
  const viewProj = mat4.multiply(mat4.create(), proj, view) as Float32Array;
  return { mode: fixed ? 'fixed' : 'adaptive', fixedFactor: fixed ?? 1, lodScale, viewProj, eye, viewportHeight: 720, fovY: Math.PI / 4 };
}
