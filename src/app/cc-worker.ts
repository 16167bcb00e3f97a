/**
 * A Web Worker that builds the Catmull-Clark data of a cage (src/gpu/cc/build.ts: topology only
 * now, tens of ms on most models, ~0.5 s on an 9k-triangle cage) off the page's thread, and hands
 * the typed arrays back without copying them. (Cheap enough for the page's thread now; whether
 * to keep the worker is the demo's call.)
 *
 *   in:  { id, cage }                       (a Cage: plain data, structured-cloned)
 *   out: { id, ok: true, data, ms } | { id, ok: false, message }
 */
import type { Cage } from '../mesh/types.ts';
import { prepareMesh } from '../gpu/prepare.ts';
import { buildCatmullClark, type CatmullClarkData } from '../gpu/cc/build.ts';

export interface CcRequest {
  id: number;
  cage: Cage;
}

export type CcReply = { id: number; ok: true; data: CatmullClarkData; ms: number } | { id: number; ok: false; message: string };

/** The tables of `cage`, built exactly as the page's tessellator will prepare it. */
export function buildTables(cage: Cage): CatmullClarkData {
  return buildCatmullClark(cage, prepareMesh(cage));
}

/** The distinct buffers behind a result's typed arrays (a buffer listed twice cannot be transferred). */
export function transferables(data: CatmullClarkData): ArrayBuffer[] {
  const buffers = new Set<ArrayBuffer>();
  for (const v of Object.values(data)) if (ArrayBuffer.isView(v) && v.buffer instanceof ArrayBuffer) buffers.add(v.buffer);
  return [...buffers];
}

// Only inside a worker (the module is also imported by tests and by the main-thread fallback).
const scope = globalThis as unknown as { document?: unknown; onmessage: unknown; postMessage(message: unknown, transfer?: Transferable[]): void };
if (typeof scope.document === 'undefined' && typeof (globalThis as { WorkerGlobalScope?: unknown }).WorkerGlobalScope !== 'undefined') {
  scope.onmessage = (e: MessageEvent<CcRequest>) => {
    const { id, cage } = e.data;
    const t0 = performance.now();
    try {
      const data = buildTables(cage);
      const reply: CcReply = { id, ok: true, data, ms: performance.now() - t0 };
      scope.postMessage(reply, transferables(data));
    } catch (err) {
      const reply: CcReply = { id, ok: false, message: (err as Error)?.message ?? String(err) };
      scope.postMessage(reply);
    }
  };
}
