/**
 * The Catmull-Clark data of each model (src/gpu/cc/build.ts: topology only) and the tessellator's
 * prepared mesh it is built from (src/app/surface-data.ts), prepared once per cage and cached:
 * switching surfaces, going back to a model seen before, or recovering from a lost device reuses
 * it. Small cages (tens of milliseconds) are prepared on the page's thread; from OFF_THREAD_FACES
 * faces on, in a worker (src/app/prepare-worker.ts), where a 40,000-face cage's second of work
 * no longer freezes the page.
 */
import { faceCount } from '../mesh/types.ts';
import type { Cage } from '../mesh/types.ts';
import type { CatmullClarkData } from '../gpu/cc/build.ts';
import { errorMessage } from './controller.ts';
import type { PrepareReply } from './prepare-worker.ts';
import { prepareSurfaceData, type SurfaceData } from './surface-data.ts';
import { runWorkerOnce } from './worker-once.ts';

export type CcTables = SurfaceData;

/** Faces from which a cage is prepared in a worker: below, the work (~0.1 s at 4,000 faces) costs
 * less than starting one. */
export const OFF_THREAD_FACES = 4096;

/** `cage`'s surface data, prepared in a worker (or here, where there are no workers: Node). */
function prepareOffThread(cage: Cage): Promise<SurfaceData> {
  if (typeof Worker === 'undefined') return Promise.resolve().then(() => prepareSurfaceData(cage));
  return runWorkerOnce(
    () => new Worker(new URL('./prepare-worker.ts', import.meta.url), { type: 'module', name: 'prepare the surface' }),
    { cage },
    (r: PrepareReply) => {
      if ('prepared' in r) return r.prepared;
      throw new Error(r.error);
    },
    (message) => new Error(`the surface preparation stopped: ${message || 'worker error'}`),
  );
}

export class CcTableCache {
  #cache = new WeakMap<Cage, Promise<CcTables>>();
  #done = new WeakSet<Cage>();

  /** Whether the data of `cage` is already prepared (or refused): no need to say "preparing". */
  has(cage: Cage): boolean {
    return this.#done.has(cage);
  }

  /** The data of `cage`; rejects with a message fit to show when the preparation refuses the cage. */
  get(cage: Cage): Promise<CcTables> {
    let p = this.#cache.get(cage);
    if (!p) {
      p = this.#prepare(cage);
      p.then(
        () => this.#done.add(cage),
        () => this.#done.add(cage),
      );
      this.#cache.set(cage, p);
    }
    return p;
  }

  async #prepare(cage: Cage): Promise<CcTables> {
    if (faceCount(cage) >= OFF_THREAD_FACES) return prepareOffThread(cage);
    // Let the page paint what it shows meanwhile (the cage and the "preparing" state) first.
    await new Promise((r) => setTimeout(r, 0));
    return prepareSurfaceData(cage);
  }
}

/**
 * The same data once it has arrived (or why it cannot), for the views that draw without waiting
 * for it: the error views' exact reference and a Catmull-Clark comparison, which the controller
 * does not prepare it for. `arrived` runs when a cage's data settles.
 */
export class ArrivedTables {
  readonly #done = new WeakMap<Cage, CcTables | string>();
  readonly #asked = new WeakSet<Cage>();
  readonly #cache: CcTableCache;
  readonly #arrived: () => void;

  constructor(cache: CcTableCache, arrived: () => void) {
    this.#cache = cache;
    this.#arrived = arrived;
  }

  /** The tables of `cage` if they have arrived; else asks for them and answers null. A refused
   * cage answers its reason. */
  get(cage: Cage): CatmullClarkData | string | null {
    const done = this.#done.get(cage);
    if (done !== undefined) return typeof done === 'string' ? done : done.data;
    if (!this.#asked.has(cage)) {
      this.#asked.add(cage);
      this.#cache
        .get(cage)
        .then(
          (t) => this.#done.set(cage, t),
          (e: unknown) => this.#done.set(cage, errorMessage(e)),
        )
        .finally(this.#arrived);
    }
    return null;
  }

  /** Why the cage's data cannot be had, once that is known (null otherwise). */
  refusal(cage: Cage): string | null {
    const done = this.#done.get(cage);
    return typeof done === 'string' ? done : null;
  }
}
