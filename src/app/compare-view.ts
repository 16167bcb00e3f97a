/**
 * The comparison view's right half (`compare=`): its own tessellator with the model's cage on it,
 * whether it owes a build, the cage/surface it refused (drawn as nothing, with the reason in the
 * stats), and the labels over the two halves. The left half is the demo's surface
 * (src/app/tessellation-demo.ts draws both).
 */
import { SideLabels } from './side-labels.ts';
import type { CatmullClarkData } from '../gpu/cc/build.ts';
import type { Cage } from '../mesh/types.ts';
import { errorMessage } from './controller.ts';
import type { DisplacementSettings, HeightEntry } from './displacement.ts';
import { TessellatorGeometry } from './geometry.ts';
import type { LoadedModel } from './models.ts';
import type { CompareSurface } from './params.ts';
import { preparedAhead, SURFACE_NAMES } from './surfaces.ts';
import { showToast } from './ui.ts';

export class CompareView {
  /** The right half's tessellator (made on first use), and the cage it holds. */
  tessellator: TessellatorGeometry | null = null;
  #cage: Cage | null = null;
  /** A build is owed: a new cage, new tables, or a new tessellator. */
  dirty = true;
  #refused: { cage: Cage; surface: CompareSurface; message: string } | null = null;
  readonly #labels = new SideLabels('compare');

  /** Another surface is asked for (or none): the tessellator goes. */
  reset(): void {
    this.tessellator?.destroy();
    this.tessellator = null;
    this.#cage = null;
    this.dirty = true;
  }

  /** The device is lost: its tessellator is garbage. */
  deviceLost(): void {
    this.tessellator = null;
    this.#cage = null;
  }

  /** The tessellator holds `cage` (its build measures that model). */
  holds(cage: Cage): boolean {
    return this.tessellator !== null && this.#cage === cage;
  }

  /** Why `surface` refused `cage` (null: it did not). */
  refusal(cage: Cage | undefined, surface: CompareSurface | null): string | null {
    const r = this.#refused;
    return r && r.cage === cage && r.surface === surface ? r.message : null;
  }

  /** The tessellator of `want` with `model`'s cage on it, made or re-uploaded as needed; null
   * while its data is not there (`tables` answers null), or when it refused the cage. */
  prepare(
    device: GPUDevice,
    capacity: number,
    model: LoadedModel,
    want: CompareSurface,
    tables: () => CatmullClarkData | string | null,
    height: HeightEntry | undefined,
    displacement: DisplacementSettings,
  ): TessellatorGeometry | null {
    if (this.refusal(model.cage, want) !== null) return null;
    let cc: CatmullClarkData | undefined;
    if (preparedAhead(want)) {
      const t = tables();
      if (t === null) return null;
      if (typeof t === 'string') {
        this.#refused = { cage: model.cage, surface: want, message: t };
        return null;
      }
      cc = t;
    }
    if (this.tessellator && this.tessellator.surface !== want) {
      this.tessellator.destroy();
      this.tessellator = null;
    }
    this.tessellator ??= new TessellatorGeometry(device, capacity, want);
    if (this.#cage !== model.cage) {
      this.#cage = null;
      try {
        // Displaced as the left half is (the error views measure the surfaces before displacement).
        this.tessellator.setCage(model.cage, cc, height?.height ?? null);
        this.tessellator.setDisplacement(displacement);
      } catch (e) {
        this.#refused = { cage: model.cage, surface: want, message: errorMessage(e) };
        showToast(errorMessage(e), {
          kind: 'info',
          title: `No ${SURFACE_NAMES[want]} surface to compare for ${model.title}`,
          timeout: 10_000,
        });
        return null;
      }
      this.#cage = model.cage;
      this.dirty = true;
    }
    return this.tessellator;
  }

  /** The labels over the two halves (and the line between them): shown with `text` (left, right)
   * when `on`, else hidden. */
  showLabels(on: boolean, text: () => [string, string]): void {
    this.#labels.show(on, text);
  }
}
