/**
 * The renderer's GPU timing (RendererOptions.timestamps): which passes it times, and the query
 * set and buffers their timestamps go through on the way back to the CPU (Renderer.readTimings).
 */
export const TIMED_PASSES = ['shadow', 'lit'] as const;
/** Timing slots: one per region of a split view (DrawOptions.region.slot). */
export const TIMING_SLOTS = 2;

/** The timestamps' query set, resolve and readback buffers, and where the readback stands. */
export interface RenderTiming {
  querySet: GPUQuerySet;
  resolve: GPUBuffer;
  read: GPUBuffer;
  state: 'idle' | 'copied' | 'mapping';
  last: Record<string, number>;
  /** The slots the copied frame wrote. */
  slots: number;
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
    read: device.createBuffer({
      label: 'render timestamps readback',
      size: count * 8,
      usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST,
    }),
    state: 'idle',
    last: {},
    slots: 1,
  };
}
