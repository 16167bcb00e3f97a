/**
 * A large cage's surface preparation off the page's main thread (src/app/cc-tables.ts sends the
 * cages big enough for it to matter): the tessellator's mesh (prepareMesh) and the exact surface's
 * tables (buildCatmullClark), about a second of CPU on a 40,000-face cage, which froze the tab
 * there. In: the cage (copied). Out: the prepared mesh and the tables with their typed arrays
 * transferred, or the refusal's message.
 */
import type { Cage } from '../mesh/types.ts';
import { buffersOf } from './transfer.ts';
import { prepareSurfaceData, type SurfaceData } from './surface-data.ts';

export type PrepareReply = { prepared: SurfaceData } | { error: string };

self.onmessage = (e: MessageEvent<{ cage: Cage }>) => {
  const post = (reply: PrepareReply, transfer: Transferable[] = []) => (self as unknown as Worker).postMessage(reply, transfer);
  try {
    const prepared = prepareSurfaceData(e.data.cage);
    post({ prepared }, [...buffersOf(prepared)]);
  } catch (err) {
    post({ error: err instanceof Error ? err.message : String(err) });
  }
};
