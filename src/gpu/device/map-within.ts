/**
 * Map a readback buffer, but give up if the map has not settled within a deadline.
 *
 * Why: on some drivers (seen with Debian's Chromium 156 on SwiftShader) the map of a buffer that
 * timestamp queries were resolved into settles late or never. A reader that waits on it forever
 * holds its state at "mapping", and whatever waits behind it (the stats' rows) reads "…" for
 * good. After `ms` the pending map is cancelled (unmap() of a pending map rejects its promise
 * with an AbortError, by the WebGPU specification) and MapStalled is thrown: the caller stops
 * timing rather than wait again.
 */
export class MapStalled extends Error {
  constructor(label: string, ms: number) {
    super(`${label}: the buffer's map did not settle within ${ms} ms`);
    this.name = 'MapStalled';
  }
}

/** How long a timing read may take before it counts as stalled. A frame's work on SwiftShader
 * under load takes seconds at the demo's largest settings, so the deadline is generous: what it
 * guards against is a map that never comes back, not a slow one. */
export const TIMING_MAP_DEADLINE_MS = 15_000;

/** GPUMapMode.READ, without touching the global (absent in unit tests). */
const GPU_MAP_MODE_READ = 0x0001;

/** The part of GPUBuffer this needs (tests pass a fake). */
export interface MappableBuffer {
  readonly label: string;
  mapAsync(mode: number, offset?: number, size?: number): Promise<void>;
  unmap(): void;
}

export interface DeadlineTimers {
  setTimeout(fn: () => void, ms: number): unknown;
  clearTimeout(id: unknown): void;
}

const realTimers: DeadlineTimers = {
  setTimeout: (fn, ms) => setTimeout(fn, ms),
  clearTimeout: (id) => clearTimeout(id as ReturnType<typeof setTimeout>),
};

/** Resolves when `buffer` is mapped for reading; rejects with MapStalled after `ms`, with the
 * map cancelled, and with the map's own error where it fails (a lost device). */
export async function mapWithin(buffer: MappableBuffer, ms: number, timers: DeadlineTimers = realTimers): Promise<void> {
  let stalled = false;
  const timer = timers.setTimeout(() => {
    stalled = true;
    try {
      buffer.unmap(); // cancels the pending map: its promise rejects
    } catch {
      // already unmapped or destroyed: nothing is pending
    }
  }, ms);
  try {
    await buffer.mapAsync(GPU_MAP_MODE_READ);
  } catch (err) {
    if (stalled) throw new MapStalled(buffer.label, ms);
    throw err;
  } finally {
    timers.clearTimeout(timer);
  }
}
