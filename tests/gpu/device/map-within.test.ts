// A timing readback whose map never settles must not hold anything behind it: mapWithin cancels
// it after its deadline, and a PassTimer whose map stalled times no further pass (the demo's
// stats then say so instead of reading "…" for good).
import { afterEach, describe, expect, it, vi } from 'vitest';
import { MapStalled, mapWithin, TIMING_MAP_DEADLINE_MS, type MappableBuffer } from '../../../src/gpu/device/map-within.ts';
import { PassTimer } from '../../../src/gpu/device/pass-timer.ts';

/** A buffer whose map settles only when told to, and whose unmap cancels a pending map as the
 * WebGPU specification says (the promise rejects with an AbortError). */
class FakeBuffer implements MappableBuffer {
  label = 'fake readback';
  unmaps = 0;
  size = 64;
  #pending: { resolve: () => void; reject: (e: Error) => void } | null = null;
  mapAsync(): Promise<void> {
    return new Promise((resolve, reject) => {
      this.#pending = { resolve, reject };
    });
  }
  settle(): void {
    this.#pending?.resolve();
    this.#pending = null;
  }
  fail(err: Error): void {
    this.#pending?.reject(err);
    this.#pending = null;
  }
  unmap(): void {
    this.unmaps++;
    if (this.#pending) this.fail(new DOMException('unmapped while pending', 'AbortError'));
  }
  getMappedRange(): ArrayBuffer {
    return new BigUint64Array([0n, 2_000_000n, 5_000_000n, 5_500_000n]).buffer;
  }
  destroy(): void {}
}

afterEach(() => {
  vi.useRealTimers();
});

describe('mapWithin', () => {
  it('resolves when the map settles in time, and cancels nothing', async () => {
    vi.useFakeTimers();
    const buf = new FakeBuffer();
    const mapped = mapWithin(buf, 1000);
    vi.advanceTimersByTime(999);
    buf.settle();
    await expect(mapped).resolves.toBeUndefined();
    vi.advanceTimersByTime(10_000);
    expect(buf.unmaps).toBe(0);
  });

  it('cancels a map that never settles and throws MapStalled', async () => {
    vi.useFakeTimers();
    const buf = new FakeBuffer();
    const mapped = mapWithin(buf, 1000);
    const caught = mapped.catch((e: unknown) => e);
    vi.advanceTimersByTime(1000);
    const err = await caught;
    expect(err).toBeInstanceOf(MapStalled);
    expect(String(err)).toContain('did not settle within 1000 ms');
    expect(buf.unmaps).toBe(1);
  });

  it("passes a map's own failure (a lost device) through unchanged", async () => {
    vi.useFakeTimers();
    const buf = new FakeBuffer();
    const mapped = mapWithin(buf, 1000);
    const lost = new Error('device lost');
    buf.fail(lost);
    await expect(mapped).rejects.toBe(lost);
    expect(buf.unmaps).toBe(0);
  });
});

describe('PassTimer with a readback that never settles', () => {
  // GPUBufferUsage is a browser global; the timer only reads its flags.
  vi.stubGlobal('GPUBufferUsage', { MAP_READ: 1, COPY_DST: 8, COPY_SRC: 4, QUERY_RESOLVE: 512 });
  function fakeDevice(readBuffers: FakeBuffer[]) {
    return {
      createQuerySet: (d: { count: number }) => ({ count: d.count, destroy() {} }),
      createBuffer: () => {
        const b = new FakeBuffer();
        readBuffers.push(b);
        return b;
      },
    } as unknown as GPUDevice;
  }
  function fakeEncoder(passes: GPUComputePassDescriptor[]) {
    return {
      beginComputePass: (d: GPUComputePassDescriptor) => {
        passes.push(d);
        return {} as GPUComputePassEncoder;
      },
      resolveQuerySet() {},
      copyBufferToBuffer() {},
    } as unknown as GPUCommandEncoder;
  }

  it('reads the stages when the map settles', async () => {
    const buffers: FakeBuffer[] = [];
    const timer = new PassTimer(fakeDevice(buffers), 't', 2);
    const passes: GPUComputePassDescriptor[] = [];
    const enc = fakeEncoder(passes);
    timer.beginPass(enc, 'a', 'factors');
    timer.beginPass(enc, 'b', 'emit');
    timer.resolve(enc);
    const read = timer.read();
    buffers[1].settle();
    expect(await read).toEqual({ factors: 2, emit: 0.5 });
    expect(passes.every((p) => p.timestampWrites)).toBe(true);
  });

  it('stops timing after the deadline instead of waiting for good', async () => {
    vi.useFakeTimers();
    const buffers: FakeBuffer[] = [];
    const timer = new PassTimer(fakeDevice(buffers), 't', 2);
    const passes: GPUComputePassDescriptor[] = [];
    const enc = fakeEncoder(passes);
    timer.beginPass(enc, 'a', 'factors');
    timer.resolve(enc);
    const read = timer.read().catch((e: unknown) => e);
    vi.advanceTimersByTime(TIMING_MAP_DEADLINE_MS);
    expect(await read).toBeInstanceOf(MapStalled);
    expect(timer.stalled).toBe(true);
    // Later passes are not timed, and a read answers at once with nothing.
    timer.beginPass(enc, 'a', 'factors');
    timer.resolve(enc);
    expect(passes.at(-1)?.timestampWrites).toBeUndefined();
    await expect(timer.read()).resolves.toEqual({});
  });
});

describe('PassTimer and the timestamp ring: a sequence submitted while a read is in flight is timed too', () => {
  vi.stubGlobal('GPUBufferUsage', { MAP_READ: 1, COPY_DST: 8, COPY_SRC: 4, QUERY_RESOLVE: 512 });
  /** Read buffers whose mapped contents say which copy they hold: [0, k ms] for copy k. */
  class TaggedBuffer extends FakeBuffer {
    ms = 0;
    override getMappedRange(): ArrayBuffer {
      return new BigUint64Array([0n, BigInt(this.ms * 1e6)]).buffer;
    }
  }
  function timerWith(): { timer: PassTimer; reads: TaggedBuffer[]; copy: (ms: number) => void } {
    const reads: TaggedBuffer[] = [];
    let made = 0;
    const device = {
      createQuerySet: (d: { count: number }) => ({ count: d.count, destroy() {} }),
      // The first buffer is the resolve buffer; the rest are the ring's readbacks.
      createBuffer: () => {
        if (made++ === 0) return new FakeBuffer();
        const b = new TaggedBuffer();
        reads.push(b);
        return b;
      },
    } as unknown as GPUDevice;
    const timer = new PassTimer(device, 't', 1);
    const copy = (ms: number) => {
      const enc = {
        beginComputePass: () => ({}) as GPUComputePassEncoder,
        resolveQuerySet() {},
        copyBufferToBuffer(_s: unknown, _so: number, dst: TaggedBuffer) {
          dst.ms = ms;
        },
      } as unknown as GPUCommandEncoder;
      timer.beginPass(enc, 'build', 'build');
      timer.resolve(enc);
    };
    return { timer, reads, copy };
  }

  it('reads the newest sequence, and the one that landed during the read after it', async () => {
    const { timer, reads, copy } = timerWith();
    copy(1);
    const first = timer.read();
    // A build lands while the first read maps: it is copied into another buffer, not dropped.
    copy(2);
    expect(timer.unread).toBe(true);
    reads[0].settle();
    expect(await first).toEqual({ build: 1 });
    const second = timer.read();
    reads[1].settle();
    expect(await second).toEqual({ build: 2 });
    expect(timer.unread).toBe(false);
  });

  it('with every buffer taken, gives up the oldest unread copy, never the newest', async () => {
    const { timer, reads, copy } = timerWith();
    copy(1);
    const first = timer.read(); // maps reads[0]
    copy(2);
    copy(3);
    copy(4); // reads[1] and reads[2] hold 2 and 3: the oldest (2) gives way to 4
    reads[0].settle();
    expect(await first).toEqual({ build: 1 });
    const next = timer.read();
    reads[1].settle();
    expect(await next).toEqual({ build: 4 });
    // 3 was older than 4: released unread.
    expect(timer.unread).toBe(false);
  });
});
