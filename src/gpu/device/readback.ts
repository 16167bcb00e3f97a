/** Copy GPU buffers back to the CPU (checks, the headless CLI, benchmarks). */
export async function readBuffer(device: GPUDevice, src: GPUBuffer, bytes: number, offset = 0): Promise<ArrayBuffer> {
  const size = Math.max(4, Math.ceil(bytes / 4) * 4);
  const staging = device.createBuffer({ label: 'readback', size, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
  const enc = device.createCommandEncoder({ label: 'readback' });
  enc.copyBufferToBuffer(src, offset, staging, 0, size);
  device.queue.submit([enc.finish()]);
  await staging.mapAsync(GPUMapMode.READ);
  const out = staging.getMappedRange().slice(0, bytes);
  staging.unmap();
  staging.destroy();
  return out;
}

import type { TessellatedMesh } from '../contract/tessellated-mesh.ts';

export interface MeshReadback {
  vertexCount: number;
  triangleCount: number;
  scale: number;
  /** The budget candidate taken (contract/tess.ts BUDGET_SCALES): 0 at scale 1. */
  budgetCandidate: number;
  positions: Float32Array;
  normals: Float32Array;
  bary: Uint32Array;
  srcTri: Uint32Array;
  indices: Uint32Array;
}

/** The whole output mesh of the last rebuild. */
export async function readMesh(device: GPUDevice, out: TessellatedMesh): Promise<MeshReadback> {
  const counts = new Uint32Array(await readBuffer(device, out.counts, 16));
  const [vertexCount, triangleCount] = counts;
  const scale = new Float32Array(counts.buffer)[2];
  const [positions, normals, bary, srcTri, indices] = await Promise.all([
    readBuffer(device, out.positions, 12 * vertexCount),
    readBuffer(device, out.normals, 12 * vertexCount),
    readBuffer(device, out.bary, 4 * vertexCount),
    readBuffer(device, out.srcTri, 4 * vertexCount),
    readBuffer(device, out.indices, 12 * triangleCount),
  ]);
  return {
    vertexCount,
    triangleCount,
    scale,
    budgetCandidate: counts[3],
    positions: new Float32Array(positions),
    normals: new Float32Array(normals),
    bary: new Uint32Array(bary),
    srcTri: new Uint32Array(srcTri),
    indices: new Uint32Array(indices),
  };
}
