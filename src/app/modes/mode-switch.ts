/**
 * The demo's current mode object: kept while pick-mode.ts gives the same answer, released and
 * replaced when the answer changes. DOM-free and GPU-free (tests/app/pick-mode.test.ts).
 */
import type { ModeId } from './pick-mode.ts';

export interface Switchable {
  readonly id: ModeId;
  /** Let go of what only this mode shows (it is no longer drawn). */
  release(): void;
}

export class ModeSwitch<M extends Switchable> {
  readonly #make: (id: ModeId) => M;
  #current: M;

  /** `make`: a new mode object for an id. The first one is the compute tessellator's. */
  constructor(make: (id: ModeId) => M) {
    this.#make = make;
    this.#current = make('compute');
  }

  get current(): M {
    return this.#current;
  }

  /** The mode object of `id`: the current one, or (the current one released) a new one. */
  to(id: ModeId): M {
    if (id !== this.#current.id) {
      this.#current.release();
      this.#current = this.#make(id);
    }
    return this.#current;
  }
}
