/**
 * A small ring of readback buffers for timestamp queries, so that every timed submission can be
 * read, not only those that came while no read was in flight.
 *
 * Why a ring: a buffer that is being mapped cannot be copied into. With one readback buffer, a
 * build or frame submitted while the last one's timestamps were mapping went untimed, and where
 * the page draws on demand no later one came: the stats kept the older figure for good (a LOD
 * change during a read showed the previous build's milliseconds). With three buffers one can be
 * mapping, one hold the newest copy and one take the next; a submission finds no free buffer only
 * when two copies wait unread, and then the older of those is what gets dropped (the newest is
 * what the stats want).
 *
 * Use: acquire() while encoding (the copy's destination, or null: untimed), submit, then
 * readLatest() maps the newest copied buffer (older unread copies are released unread). `unread`
 * says whether a copy is waiting, so a caller reads again after a read that was overtaken.
 */
import { mapWithin, MapStalled, type MappableBuffer, TIMING_MAP_DEADLINE_MS } from './map-within.ts';

/** The part of GPUBuffer the ring needs (tests pass a fake). */
export interface RingBuffer extends MappableBuffer {
  getMappedRange(): ArrayBuffer;
  destroy(): void;
}

interface Entry<M> {
  buffer: RingBuffer;
  state: 'free' | 'copied' | 'mapping';
  /** Order of acquisition: the newest copied entry is the one read. */
  serial: number;
  meta: M | null;
}

export class TimestampRing<M> {
  readonly #entries: Entry<M>[];
  #serial = 0;
  #stalled = false;
  #destroyed = false;
  #reading: Promise<{ meta: M; ticks: BigInt64Array } | null> | null = null;

  constructor(
    buffers: RingBuffer[],
    private readonly deadlineMs = TIMING_MAP_DEADLINE_MS,
  ) {
    this.#entries = buffers.map((buffer) => ({ buffer, state: 'free', serial: 0, meta: null }));
  }

  /** A map did not settle within the deadline: nothing is timed any more. */
  get stalled(): boolean {
    return this.#stalled;
  }

  /** A copy is waiting to be read (it came after the read in flight, if any). */
  get unread(): boolean {
    return this.#entries.some((e) => e.state === 'copied');
  }

  /**
   * The buffer to copy this submission's timestamps into, marked as holding `meta`; null when
   * timing stopped. When every buffer is taken, the oldest copy not being mapped is given up.
   */
  acquire(meta: M): RingBuffer | null {
    if (this.#stalled || this.#destroyed) return null;
    let e = this.#entries.find((x) => x.state === 'free');
    if (!e) {
      const copied = this.#entries.filter((x) => x.state === 'copied').sort((a, b) => a.serial - b.serial);
      e = copied[0];
    }
    if (!e) return null;
    e.state = 'copied';
    e.serial = ++this.#serial;
    e.meta = meta;
    return e.buffer;
  }

  /**
   * The newest copy's timestamps and its meta (null when none is waiting). Call after submitting
   * the commands that copied it. A call while a read is in flight gets that read's answer.
   */
  readLatest(): Promise<{ meta: M; ticks: BigInt64Array } | null> {
    if (this.#destroyed) return Promise.resolve(null);
    this.#reading ??= this.#map().finally(() => {
      this.#reading = null;
    });
    return this.#reading;
  }

  async #map(): Promise<{ meta: M; ticks: BigInt64Array } | null> {
    const copied = this.#entries.filter((x) => x.state === 'copied').sort((a, b) => b.serial - a.serial);
    const e = copied[0];
    if (!e) return null;
    // Older copies are superseded: free them unread.
    for (const old of copied.slice(1)) old.state = 'free';
    e.state = 'mapping';
    try {
      await mapWithin(e.buffer, this.deadlineMs);
    } catch (err) {
      if (err instanceof MapStalled) this.#stalled = true;
      e.state = 'free';
      throw err;
    }
    if (this.#destroyed) return null;
    const ticks = new BigInt64Array(e.buffer.getMappedRange().slice(0));
    e.buffer.unmap();
    e.state = 'free';
    return { meta: e.meta as M, ticks };
  }

  destroy(): void {
    this.#destroyed = true;
    for (const e of this.#entries) e.buffer.destroy();
  }
}

/** How many readback buffers a ring holds (see the header). */
export const RING_SIZE = 3;
