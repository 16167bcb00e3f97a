/**
 * The compute tessellator's pipelines on the page's device, per surface: compiled asynchronously
 * (src/gpu/tess/pipelines.ts createTessPipelinesAsync) the first time a surface is asked for, and
 * kept, so a tessellator made for that surface again (a switch back, another model) waits for
 * nothing. Only what is asked for is compiled: the first view compiles the surface it shows.
 */
import { createTessPipelinesAsync, type TessPipelines } from '../gpu/tess/pipelines.ts';
import type { Surface } from '../gpu/tess/passes.ts';

export class TessPipelineCache {
  readonly #pending = new Map<Surface, Promise<TessPipelines>>();
  readonly #ready = new Map<Surface, TessPipelines>();
  /** Passes compiled so far, of how many, for the surfaces in flight (what the page says it waits for). */
  #progress = new Map<Surface, [number, number]>();

  constructor(
    private readonly device: GPUDevice,
    private readonly onProgress: () => void = () => {},
  ) {}

  /** The set for `surface` if it is compiled. */
  get(surface: Surface): TessPipelines | undefined {
    return this.#ready.get(surface);
  }

  /** `surface`'s set, compiled now if it is not yet (one compile per surface however often asked). */
  prepare(surface: Surface): Promise<TessPipelines> {
    let p = this.#pending.get(surface);
    if (!p) {
      p = createTessPipelinesAsync(this.device, surface, (done, total) => {
        this.#progress.set(surface, [done, total]);
        this.onProgress();
      }).then((set) => {
        this.#ready.set(surface, set);
        this.#progress.delete(surface);
        return set;
      });
      this.#pending.set(surface, p);
      p.catch(() => {
        this.#pending.delete(surface);
        this.#progress.delete(surface);
      });
    }
    return p;
  }

  /** [compiled, total] for `surface` while it compiles; null when it is not compiling. */
  progress(surface: Surface): [number, number] | null {
    if (this.#ready.has(surface) || !this.#pending.has(surface)) return null;
    return this.#progress.get(surface) ?? [0, 0];
  }
}
