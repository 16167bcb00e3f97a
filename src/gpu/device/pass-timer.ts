/**
 * GPU time per stage of a sequence of compute passes, from timestamp queries: each pass begun
 * through beginPass writes a pair of timestamps (while the query set lasts); resolve() after the
 * last pass copies them into a free readback buffer of a small ring (timestamp-ring.ts), so a
 * sequence submitted while an earlier one is being read is timed too; read() maps the newest and
 * sums the milliseconds by stage name.
 */
import { RING_SIZE, TimestampRing } from './timestamp-ring.ts';

export class PassTimer {
  /** The timestamps' map did not settle (mapWithin): no pass is timed any more. */
  get stalled(): boolean {
    return this.ring.stalled;
  }
  private readonly set: GPUQuerySet;
  private readonly resolveBuf: GPUBuffer;
  private readonly ring: TimestampRing<string[]>;
  /** destroy() ran: a read asked after it (e.g. by stats that outlive a tessellator the page has
   * freed) gets {} rather than a map of a destroyed buffer. */
  private destroyed = false;
  /** The stages of the sequence being recorded (one per pass). */
  private recording: string[] = [];

  constructor(device: GPUDevice, label: string, passes: number) {
    const count = 2 * passes;
    this.set = device.createQuerySet({ label: `${label} timestamps`, type: 'timestamp', count });
    this.resolveBuf = device.createBuffer({
      label: `${label} timestamps resolve`,
      size: 8 * count,
      usage: GPUBufferUsage.QUERY_RESOLVE | GPUBufferUsage.COPY_SRC,
    });
    const reads = Array.from({ length: RING_SIZE }, (_, i) =>
      device.createBuffer({
        label: `${label} timestamps read ${i}`,
        size: 8 * count,
        usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
      }),
    );
    this.ring = new TimestampRing(reads);
  }

  /** A resolved sequence waits to be read (submitted after the read in flight, if any). */
  get unread(): boolean {
    return this.ring.unread;
  }

  /** Begin a compute pass, timed as `stage` when a pair of queries is free. */
  beginPass(encoder: GPUCommandEncoder, label: string, stage: string): GPUComputePassEncoder {
    const query = 2 * this.recording.length;
    const desc: GPUComputePassDescriptor = { label };
    if (!this.stalled && !this.destroyed && query + 2 <= this.set.count) {
      desc.timestampWrites = { querySet: this.set, beginningOfPassWriteIndex: query, endOfPassWriteIndex: query + 1 };
      this.recording.push(stage);
    }
    return encoder.beginComputePass(desc);
  }

  /** After the sequence's last pass: copy its timestamps out for read(). */
  resolve(encoder: GPUCommandEncoder): void {
    const queries = 2 * this.recording.length;
    const target = queries ? this.ring.acquire(this.recording) : null;
    if (target) {
      encoder.resolveQuerySet(this.set, 0, queries, this.resolveBuf, 0);
      encoder.copyBufferToBuffer(this.resolveBuf, 0, target as GPUBuffer, 0, 8 * queries);
    }
    this.recording = [];
  }

  /** Milliseconds per stage of the newest resolved sequence ({} when none waits); call after
   * submitting it. A second call while a read is in flight gets the same answer. */
  async read(): Promise<Record<string, number>> {
    if (this.destroyed) return {};
    const got = await this.ring.readLatest();
    if (!got) return {};
    const out: Record<string, number> = {};
    got.meta.forEach((stage, i) => {
      const ns = Number(got.ticks[2 * i + 1] - got.ticks[2 * i]);
      out[stage] = (out[stage] ?? 0) + ns / 1e6;
    });
    return out;
  }

  destroy(): void {
    this.destroyed = true;
    this.set.destroy();
    this.resolveBuf.destroy();
    this.ring.destroy();
  }
}
