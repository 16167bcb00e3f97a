/**
 * The Catmull-Clark data of each model (src/gpu/cc/build.ts: topology only, tens of
 * milliseconds on most cages, about half a second on a 9k-triangle cage), prepared once per cage
 * on the page's thread and cached: switching surfaces, going back to a model seen before, or
 * recovering from a lost device reuses it. No worker: the preparation is cheaper than shipping
 * the cage to one and its typed arrays back.
 */
import type { Cage } from '../mesh/types.ts';
import { prepareMesh } from '../gpu/tess/prepare.ts';
import { buildCatmullClark, type CatmullClarkData } from '../gpu/cc/build.ts';
import { errorMessage } from './controller.ts';

export interface CcTables {
  data: CatmullClarkData;
  /** Wall-clock milliseconds of the CPU preparation. */
  ms: number;
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
    // Let the page paint what it shows meanwhile (the cage and the "preparing" state) first.
    await new Promise((r) => setTimeout(r, 0));
    const t0 = performance.now();
    const data = buildCatmullClark(cage, prepareMesh(cage));
    return { data, ms: performance.now() - t0 };
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
