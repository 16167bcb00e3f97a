/**
 * What the demo asks of the device's limits for its output buffers, and what it tells the user
 * when the device gives less. Pure (tests/app/limits.test.ts); the page shows the sentences in a
 * toast and in the stats' "limits" row.
 */
import type { LimitName } from '../gpu/device/device.ts';
import { outputCapacity } from '../gpu/tess/factors.ts';

/** Bytes per output vertex in the largest buffer (positions, float32x3) and per triangle (indices). */
const LARGEST_BYTES_PER_ELEMENT = 12;

/** The buffer limits that `capacity` output vertices and triangles need. */
export function wantedOutputLimits(capacity: number): Partial<Record<LimitName, number>> {
  const bytes = LARGEST_BYTES_PER_ELEMENT * capacity;
  return { maxStorageBufferBindingSize: bytes, maxBufferSize: bytes };
}

/**
 * The device's clamps (GpuContext.clamps), and the output capacity they leave when it is below
 * the one asked for: the budget pass then scales the factors down sooner.
 */
export function clampMessages(
  deviceClamps: readonly string[],
  limits: { maxStorageBufferBindingSize: number; maxBufferSize: number; maxStorageBuffersInVertexStage?: number },
  capacity: number,
): string[] {
  const out = [...deviceClamps];
  // src/gpu/render/renderer.ts vertexStorage; src/gpu/instanced/levels.ts checks its own count when asked for.
  if ((limits.maxStorageBuffersInVertexStage ?? 8) < 2)
    out.push(
      'no storage buffers in the vertex stage (WebGPU compatibility mode): the wireframe, patch colours, error heat maps and the instanced tessellator are not available; the surfaces draw as usual',
    );
  const fits = outputCapacity(limits, { vertexCapacity: capacity, triangleCapacity: capacity });
  if (fits.vertexCapacity < capacity) {
    const n = (x: number) => x.toLocaleString('en-US');
    out.push(
      `output buffers: ${n(fits.vertexCapacity)} vertices and triangles (${n(capacity)} asked for); the budget scales factors to fit`,
    );
  }
  return out;
}
