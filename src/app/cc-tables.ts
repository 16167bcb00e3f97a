/**
 * The Catmull-Clark tables of each model, built once (per cage) in a Web Worker and cached:
 * switching surfaces, or back to a model seen before, or recovering from a lost device, reuses
 * them. Without workers (or if the worker cannot start) the build runs on the page's thread,
 * after a frame has had the chance to show the "building" message.
 */
import type { Cage } from '../mesh/types.ts';
import type { CatmullClarkData } from '../gpu/cc/build.ts';
import type { CcReply, CcRequest } from './cc-worker.ts';

export interface CcTables {
  data: CatmullClarkData;
  /** Wall-clock milliseconds of the CPU build (in the worker, or on the page's thread). */
  ms: number;
  where: 'worker' | 'main thread';
}

export class CcTableCache {
  #cache = new WeakMap<Cage, Promise<CcTables>>();
  #done = new WeakSet<Cage>();
  #worker: Worker | null | undefined;
  #pending = new Map<number, { cage: Cage; resolve(t: CcTables): void; reject(e: Error): void }>();
  #nextId = 1;

  /** Whether the tables of `cage` are already built (or refused): no need to say "building". */
  has(cage: Cage): boolean {
    return this.#done.has(cage);
  }

  /** The tables of `cage`; rejects with a message fit to show when the build refuses the cage. */
  get(cage: Cage): Promise<CcTables> {
    let p = this.#cache.get(cage);
    if (!p) {
      p = this.#build(cage);
      p.then(() => this.#done.add(cage), () => this.#done.add(cage));
      this.#cache.set(cage, p);
    }
    return p;
  }

  #build(cage: Cage): Promise<CcTables> {
    const worker = this.#startWorker();
    if (!worker) return this.#buildHere(cage);
    const id = this.#nextId++;
    return new Promise<CcTables>((resolve, reject) => {
      this.#pending.set(id, { cage, resolve, reject });
      const request: CcRequest = { id, cage };
      try {
        worker.postMessage(request);
      } catch (e) {
        this.#pending.delete(id);
        reject(e instanceof Error ? e : new Error(String(e)));
      }
    });
  }

  async #buildHere(cage: Cage): Promise<CcTables> {
    // Let the page paint its "building" state first.
    await new Promise((r) => setTimeout(r, 30));
    const { buildTables } = await import('./cc-worker.ts');
    const t0 = performance.now();
    const data = buildTables(cage);
    return { data, ms: performance.now() - t0, where: 'main thread' };
  }

  #startWorker(): Worker | null {
    if (this.#worker !== undefined) return this.#worker;
    try {
      const worker = new Worker(new URL('./cc-worker.ts', import.meta.url), { type: 'module', name: 'catmull-clark tables' });
      worker.onmessage = (e: MessageEvent<CcReply>) => {
        const r = e.data;
        const waiting = this.#pending.get(r.id);
        if (!waiting) return;
        this.#pending.delete(r.id);
        if (r.ok) waiting.resolve({ data: r.data, ms: r.ms, where: 'worker' });
        else waiting.reject(new Error(r.message));
      };
      worker.onerror = (e) => {
        // The worker itself failed (it could not load): build what it held here, and from now on.
        e.preventDefault();
        console.warn(`Catmull-Clark worker failed (${e.message}); building on the page's thread`);
        this.#worker = null;
        worker.terminate();
        const pending = [...this.#pending.values()];
        this.#pending.clear();
        for (const p of pending) this.#buildHere(p.cage).then(p.resolve, p.reject);
      };
      this.#worker = worker;
    } catch {
      this.#worker = null;
    }
    return this.#worker;
  }
}
