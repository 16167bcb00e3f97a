/**
 * The compute tessellator's pipelines on the page's device, per surface: made the first time a
 * surface is asked for, and kept, so a tessellator made for that surface again (a switch back,
 * another model) compiles nothing. Only what is asked for is made: the first view makes the
 * surface it shows. `prepare` resolves once the GPU has compiled them (the device processes its
 * work in order: the queue's next "done" comes after the compiles), so the page can say that this
 * is what it waits for.
 */
import { createTessPipelines, type TessPipelines } from '../gpu/tess/pipelines.ts';
import type { Surface } from '../gpu/tess/passes.ts';

export class TessPipelineCache {
  readonly #pending = new Map<Surface, Promise<TessPipelines>>();
  readonly #ready = new Map<Surface, TessPipelines>();

  constructor(private readonly device: GPUDevice) {}

  /** The set for `surface` if it is compiled. */
  get(surface: Surface): TessPipelines | undefined {
    return this.#ready.get(surface);
  }

  /** `surface`'s set, made now if it is not yet (once per surface however often asked); resolves
   * when the GPU has compiled it. */
  prepare(surface: Surface): Promise<TessPipelines> {
    let p = this.#pending.get(surface);
    if (!p) {
      const set = createTessPipelines(this.device, surface);
      p = this.device.queue.onSubmittedWorkDone().then(() => {
        this.#ready.set(surface, set);
        return set;
      });
      this.#pending.set(surface, p);
      p.catch(() => this.#pending.delete(surface));
    }
    return p;
  }

  /** `surface`'s set is being compiled. */
  compiling(surface: Surface): boolean {
    return this.#pending.has(surface) && !this.#ready.has(surface);
  }
}
