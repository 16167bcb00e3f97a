/**
 * GPU time per stage of a sequence of compute passes, from timestamp queries: each pass begun
 * through beginPass writes a pair of timestamps (while the query set lasts, and unless the last
 * sequence's read is still in flight); resolve() after the last pass; read() maps the results and
 * sums the milliseconds by stage name.
 */
import { mapWithin, MapStalled, TIMING_MAP_DEADLINE_MS } from './map-within.ts';

export class PassTimer {
  #stalled = false;
  /** The timestamps' map did not settle (mapWithin): no pass is timed any more. */
  get stalled(): boolean {
    return this.#stalled;
  }
  private readonly set: GPUQuerySet;
  private readonly resolveBuf: GPUBuffer;
  private readonly readBuf: GPUBuffer;
  private pending = false;
  private reading?: Promise<Record<string, number>>;
  /** The stages of the sequence being recorded (one per pass), then of the one in flight. */
  private stages: string[] = [];
  private recording: string[] = [];

  constructor(device: GPUDevice, label: string, passes: number) {
    const count = 2 * passes;
    this.set = device.createQuerySet({ label: `${label} timestamps`, type: 'timestamp', count });
    this.resolveBuf = device.createBuffer({
      label: `${label} timestamps resolve`,
      size: 8 * count,
      usage: GPUBufferUsage.QUERY_RESOLVE | GPUBufferUsage.COPY_SRC,
    });
    this.readBuf = device.createBuffer({
      label: `${label} timestamps read`,
      size: 8 * count,
      usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
    });
  }

  /** Begin a compute pass, timed as `stage` when a pair of queries is free. */
  beginPass(encoder: GPUCommandEncoder, label: string, stage: string): GPUComputePassEncoder {
    const query = 2 * this.recording.length;
    const desc: GPUComputePassDescriptor = { label };
    if (!this.pending && !this.#stalled && query + 2 <= this.set.count) {
      desc.timestampWrites = { querySet: this.set, beginningOfPassWriteIndex: query, endOfPassWriteIndex: query + 1 };
      this.recording.push(stage);
    }
    return encoder.beginComputePass(desc);
  }

  /** After the sequence's last pass: copy its timestamps out for read(). */
  resolve(encoder: GPUCommandEncoder): void {
    const queries = 2 * this.recording.length;
    if (queries) {
      encoder.resolveQuerySet(this.set, 0, queries, this.resolveBuf, 0);
      encoder.copyBufferToBuffer(this.resolveBuf, 0, this.readBuf, 0, 8 * queries);
      this.stages = this.recording;
      this.pending = true;
    }
    this.recording = [];
  }

  /** Milliseconds per stage of the last resolved sequence ({} when none is pending); a second
   * call while a read is in flight gets the same answer. */
  read(): Promise<Record<string, number>> {
    if (!this.pending) return Promise.resolve({});
    this.reading ??= this.map().finally(() => {
      this.reading = undefined;
    });
    return this.reading;
  }

  private async map(): Promise<Record<string, number>> {
    try {
      await mapWithin(this.readBuf, TIMING_MAP_DEADLINE_MS);
    } catch (err) {
      if (err instanceof MapStalled) {
        this.#stalled = true;
        this.pending = false;
      }
      throw err;
    }
    const ticks = new BigUint64Array(this.readBuf.getMappedRange().slice(0));
    this.readBuf.unmap();
    this.pending = false;
    const out: Record<string, number> = {};
    this.stages.forEach((stage, i) => {
      const ns = Number(ticks[2 * i + 1] - ticks[2 * i]);
      out[stage] = (out[stage] ?? 0) + ns / 1e6;
    });
    return out;
  }

  destroy(): void {
    this.set.destroy();
    this.resolveBuf.destroy();
    this.readBuf.destroy();
  }
}
