/**
 * What the demo shows, and the one flow that changes it:
 *
 *   request (a model to load, or another surface for the current one)
 *     → the model (fetched or parsed; the page keeps the old one meanwhile)
 *     → its surface data (the Catmull-Clark tables, when that surface is asked for)
 *     → upload to the GPU (Catmull-Clark refused there too: Phong instead, and say why)
 *     → commit: the model, its data and the surface drawn change together, and the page is told.
 *
 * Something on screen at once: when the surface data of a model not shown yet takes longer than
 * `interimAfterMs`, the model is committed first as its flat cage (placed, its camera framed), and
 * the data's arrival switches the surface of the same model: the camera does not move.
 *
 * One staleness rule: every request takes the next serial number, and a flow whose serial is no
 * longer the latest stops at its next step and changes nothing (a later model or surface replaced
 * it). A failed request changes nothing either: the page keeps what it showed, and is told why.
 *
 * DOM-free and GPU-free: the page hands in `DemoPorts` (tests/app/controller.test.ts hands in fakes).
 */
import type { Surface } from './params.ts';
import { FALLBACK_SURFACE, preparedAhead } from './surfaces.ts';

/** The message of anything thrown: an Error's message (a CageError's lists the lines), else its text. */
export function errorMessage(e: unknown): string {
  if (e instanceof Error) return e.message;
  if (typeof e === 'object' && e !== null && typeof (e as { message?: unknown }).message === 'string')
    return (e as { message: string }).message;
  return String(e);
}

/** A surface as drawn (the same names as asked for: Catmull-Clark, Phong or the flat cage). */
export type Shown = Surface;

export interface DemoPorts<M extends { title: string }, D, P = void> {
  /** The surface data of a model (the Catmull-Clark tables); rejects with a message fit to show
   * when the model has none. The page's one dependency on how the data is made. */
  prepareSurface(model: M): Promise<D>;
  /** Whether prepareSurface would answer at once (a cached answer): no "building" message. */
  surfaceReady(model: M): boolean;
  /** Put `model` on the GPU to draw `surface` (`data` given exactly when it is Catmull-Clark).
   * Throws, with a message fit to show, when it cannot. */
  upload(model: M, surface: Shown, data: D | null): void;

  /** A wait the user should see ("Loading torus…"), or null when it is over. `surface`: the wait
   * for the surface asked for (its data, or whatever else the page prepares for it: the page may
   * say which, BUILDING being the controller's word for it). */
  loading(message: string | null, surface?: boolean): void;
  /** Whether the surface data is being prepared (the stats say so). */
  preparing(busy: boolean): void;
  /** A request failed; what was shown stays. `kept` is the model still shown, if any. */
  failed(title: string, message: string, kept: M | null): void;
  /** `surface` (Catmull-Clark or an ACC scheme) was asked for but `model` has none: Phong is shown instead. */
  fellBack(model: M, reason: string, surface: Surface): void;
  /** A request was committed: `model` is shown (`previous` before it; the same object when only
   * the surface changed), with what the request carried. */
  shown(model: M, previous: M | null, placement: P | undefined): void;
}

export interface DemoControllerOptions {
  /** Milliseconds of waiting for surface data before the model is shown as its flat cage
   * meanwhile (default 100: data that comes within a few frames shows no interim picture). */
  interimAfterMs?: number;
}

/** The wait for surface data, as the controller says it (the page may say more: DemoScene). */
export const BUILDING = 'Preparing subdivision data…';

export class DemoController<M extends { title: string }, D, P = void> {
  readonly #ports: DemoPorts<M, D, P>;
  readonly #interimAfterMs: number;
  #surface: Surface;
  #serial = 0;
  #version = 0;
  /** The model of the latest request (a surface change while a model loads applies to that model). */
  #latest: { model: Promise<M>; what: string; placement: P | undefined } | null = null;

  #model: M | null = null;
  #data: D | null = null;
  #dataError: string | null = null;
  #shown: Shown;
  #preparing = false;
  /** The serial of the request that set `preparing` (only it clears it). */
  #preparingFor = 0;

  constructor(ports: DemoPorts<M, D, P>, surface: Surface, options: DemoControllerOptions = {}) {
    this.#ports = ports;
    this.#interimAfterMs = options.interimAfterMs ?? 100;
    this.#surface = surface;
    this.#shown = surface;
  }

  /** The model shown (null before the first one loads). */
  get model(): M | null {
    return this.#model;
  }

  /** The surface asked for. */
  get surface(): Surface {
    return this.#surface;
  }

  /** The surface drawn: the one asked for, or Phong where Catmull-Clark has no data. */
  get shownSurface(): Shown {
    return this.#shown;
  }

  /** The shown model's surface data (kept when another surface is drawn), or null. */
  get data(): D | null {
    return this.#data;
  }

  /** Why the shown model is not drawn as the surface asked for (Catmull-Clark data or an ACC
   * scheme refused it), when it was asked for and refused. */
  get dataError(): string | null {
    return this.#surface !== this.#shown && this.#surface !== 'cage' ? this.#dataError : null;
  }

  get preparing(): boolean {
    return this.#preparing;
  }

  /** Changes whenever what is shown changes (a committed request, a re-upload): what is derived
   * from the shown state (the stats' extra counts) can key on it. */
  get version(): number {
    return this.#version;
  }

  /** Load and show a model; false when it failed (the old one stays) or a later request replaced it. */
  loadModel(load: () => Promise<M>, what: string, placement?: P): Promise<boolean> {
    const model = Promise.resolve().then(load);
    this.#latest = { model, what, placement };
    return this.#run(model, what, placement, true);
  }

  /** Show another surface, for the model shown (or the one being loaded: it will come with it). */
  setSurface(surface: Surface): Promise<boolean> {
    this.#surface = surface;
    const latest = this.#latest;
    if (!latest) return Promise.resolve(false);
    return this.#run(latest.model, latest.what, latest.placement, false);
  }

  /** Upload the shown state again (after a device loss: a new device has none of it). */
  reupload(): void {
    const model = this.#model;
    if (!model) return;
    const r = this.#upload(model, this.#shown, this.#data);
    this.#version++;
    this.#shown = r.shown;
    if (r.dataError) {
      this.#data = null;
      this.#dataError = r.dataError;
    }
  }

  async #run(modelPromise: Promise<M>, what: string, placement: P | undefined, isLoad: boolean): Promise<boolean> {
    const serial = ++this.#serial;
    const stale = () => serial !== this.#serial;
    // A surface change of a model already shown shows no "loading" (the old picture stays).
    if (isLoad) this.#ports.loading(`Loading ${what}…`);
    let model: M;
    try {
      model = await modelPromise;
    } catch (e) {
      if (stale()) return false;
      this.#fail(`Could not load ${what}`, e);
      return false;
    }
    if (stale()) return false;

    const surface = this.#surface;
    let data: D | null = model === this.#model ? this.#data : null;
    let dataError: string | null = model === this.#model ? this.#dataError : null;
    if (preparedAhead(surface) && !data) {
      const ready = this.#ports.surfaceReady(model);
      if (!ready) this.#ports.loading(BUILDING, true);
      this.#preparingFor = serial;
      this.#setPreparing(true);
      const prepared = Promise.resolve()
        .then(() => this.#ports.prepareSurface(model))
        .then(
          (d) => ({ data: d, error: null }),
          (e: unknown) => ({ data: null, error: errorMessage(e) }),
        );
      // A model not on screen yet, whose data is slow: show its flat cage meanwhile.
      if (!ready && model !== this.#model) {
        const first = await Promise.race([prepared, new Promise<null>((r) => setTimeout(() => r(null), this.#interimAfterMs))]);
        if (stale()) {
          if (this.#preparingFor === serial) this.#setPreparing(false);
          return false;
        }
        if (first === null) this.#showInterim(model, placement);
      }
      const r = await prepared;
      data = r.data;
      dataError = r.error;
      // A later request that prepares owns the flag; one that does not must not leave it set.
      if (this.#preparingFor === serial) this.#setPreparing(false);
      if (stale()) return false;
    }

    let uploaded: { shown: Shown; dataError: string | null };
    try {
      uploaded = this.#upload(model, preparedAhead(surface) && !data ? FALLBACK_SURFACE : surface, data);
    } catch (e) {
      this.#fail(`Could not tessellate ${what}`, e);
      // Put back what was shown (the GPU may hold half of the new model).
      if (this.#model) {
        try {
          this.#upload(this.#model, this.#shown, this.#data);
        } catch {
          // It uploaded before; if it cannot now, the device is going away and onInit will retry.
        }
      }
      return false;
    }
    if (uploaded.dataError) {
      data = null;
      dataError = uploaded.dataError;
    }

    const previous = this.#model;
    this.#version++;
    this.#model = model;
    this.#data = data;
    this.#dataError = dataError;
    this.#shown = uploaded.shown;
    // Say why the surface asked for is not shown when this request is what found out.
    if (dataError && uploaded.shown !== surface && (preparedAhead(surface) || uploaded.dataError))
      this.#ports.fellBack(model, dataError, surface);
    // The placement goes with the model's first showing (also when a surface change overtook its load).
    this.#ports.shown(model, previous, model !== previous ? placement : undefined);
    return true;
  }

  /** Commit `model` as its flat cage while its surface data is prepared (placed now, so that the
   * surface that follows keeps the camera). If even the cage cannot be uploaded, nothing changes:
   * the full upload that follows will say why. */
  #showInterim(model: M, placement: P | undefined): void {
    try {
      this.#ports.upload(model, 'cage', null);
    } catch {
      if (this.#model) {
        try {
          this.#ports.upload(this.#model, this.#shown, this.#data);
        } catch {
          // As in #run: the device is going away, and onInit will upload again.
        }
      }
      return;
    }
    const previous = this.#model;
    this.#version++;
    this.#model = model;
    this.#data = null;
    this.#dataError = null;
    this.#shown = 'cage';
    this.#ports.shown(model, previous, model !== previous ? placement : undefined);
    // The page ends a wait when a model is shown; this one goes on.
    this.#ports.loading(BUILDING, true);
  }

  /** Upload for `surface`; where the Catmull-Clark upload (or an ACC scheme, which needs no data
   * prepared ahead: its patches are made at upload) refuses the model, Phong instead. */
  #upload(model: M, surface: Shown, data: D | null): { shown: Shown; dataError: string | null } {
    // The flat cage and the fallback take every cage; a surface prepared ahead without its data
    // (the caller says why) is shown as the fallback.
    if (surface === 'cage' || surface === FALLBACK_SURFACE || (preparedAhead(surface) && !data)) {
      const shown = surface === 'cage' ? surface : FALLBACK_SURFACE;
      this.#ports.upload(model, shown, null);
      return { shown, dataError: null };
    }
    try {
      this.#ports.upload(model, surface, preparedAhead(surface) ? data : null);
      return { shown: surface, dataError: null };
    } catch (e) {
      this.#ports.upload(model, FALLBACK_SURFACE, null);
      return { shown: FALLBACK_SURFACE, dataError: errorMessage(e) };
    }
  }

  #fail(title: string, e: unknown): void {
    this.#ports.loading(null);
    const kept = this.#model;
    // A later surface change applies to the model still shown, not to the one that failed.
    this.#latest = kept ? { model: Promise.resolve(kept), what: kept.title, placement: undefined } : null;
    this.#ports.failed(title, errorMessage(e) + (kept ? `\n\nStill showing ${kept.title}.` : ''), kept);
  }

  #setPreparing(busy: boolean): void {
    this.#preparing = busy;
    this.#ports.preparing(busy);
  }
}
