/**
 * The renderer's GPU timing (RendererOptions.timestamps): which passes it times, and the query
 * set and buffers their timestamps go through on the way back to the CPU (Renderer.readTimings):
 * a ring of readback buffers (src/gpu/device/timestamp-ring.ts), so that a frame drawn while the
 * last one's timestamps are being read is timed too.
 */
import { RING_SIZE, TimestampRing } from '../device/timestamp-ring.ts';

export const TIMED_PASSES = ['shadow', 'lit'] as const;
/** Timing slots: one per region of a split view (DrawOptions.region.slot). */
export const TIMING_SLOTS = 2;

/** The timestamps' query set, resolve buffer and readback ring (each copy tagged with the number
 * of slots its frame wrote), and the last figures read. */
export interface RenderTiming {
  querySet: GPUQuerySet;
  resolve: GPUBuffer;
  ring: TimestampRing<number>;
  last: Record<string, number>;
}

/** A Renderer's timing resources, idle. */
export function createRenderTiming(device: GPUDevice): RenderTiming {
  const count = TIMED_PASSES.length * 2 * TIMING_SLOTS;
  return {
    querySet: device.createQuerySet({ label: 'render timestamps', type: 'timestamp', count }),
    // One 256-byte-aligned block per slot (resolveQuerySet's destination offset must be).
    resolve: device.createBuffer({
      label: 'render timestamps resolve',
      size: 256 * (TIMING_SLOTS - 1) + 8 * TIMED_PASSES.length * 2,
      usage: GPUBufferUsage.QUERY_RESOLVE | GPUBufferUsage.COPY_SRC,
    }),
    ring: new TimestampRing(
      Array.from({ length: RING_SIZE }, (_, i) =>
        device.createBuffer({
          label: `render timestamps readback ${i}`,
          size: count * 8,
          usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
        }),
      ),
    ),
    last: {},
  };
}
