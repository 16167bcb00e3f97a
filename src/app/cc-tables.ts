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
