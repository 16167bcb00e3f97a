/**
 * Reads the tessellator's `counts` (vertices, triangles, budget scale, budget candidate) back for the
 * stats panel, a few frames late and never stalling: one staging buffer, copied into only
 * when it is idle.
 */

export interface MeshCounts {
  vertexCount: number;
  triangleCount: number;
  /** 1 when the factors fitted the buffers; below 1 when the budget pass scaled them down. */
  budgetScale: number;
  /** The budget candidate taken (src/gpu/contract/tess.ts BUDGET_SCALES): 0 at scale 1. */
  budgetCandidate: number;
}

export class CountsReader {
  #staging: GPUBuffer;
  #state: 'idle' | 'copied' | 'mapping' = 'idle';

  constructor(device: GPUDevice) {
    this.#staging = device.createBuffer({
      label: 'counts readback',
      size: 16,
      usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
    });
  }

  /** Whether a copy would be taken now (no read in flight). */
  get idle(): boolean {
    return this.#state === 'idle';
  }

  /** Encode a copy of `counts` (skipped while a previous read is still in flight). */
  copy(encoder: GPUCommandEncoder, counts: GPUBuffer): void {
    if (this.#state !== 'idle') return;
    encoder.copyBufferToBuffer(counts, 0, this.#staging, 0, 16);
    this.#state = 'copied';
  }

  /** After the copy was submitted: the counts, or null if there was nothing new to read. */
  async read(): Promise<MeshCounts | null> {
    if (this.#state !== 'copied') return null;
    this.#state = 'mapping';
    try {
      await this.#staging.mapAsync(GPUMapMode.READ);
      const words = new Uint32Array(this.#staging.getMappedRange().slice(0));
      this.#staging.unmap();
      return {
        vertexCount: words[0],
        triangleCount: words[1],
        budgetScale: new Float32Array(words.buffer, 8, 1)[0],
        budgetCandidate: words[3],
      };
    } catch {
      return null; // the device went away mid-read
    } finally {
      this.#state = 'idle';
    }
  }

  destroy(): void {
    this.#staging.destroy();
  }
}
