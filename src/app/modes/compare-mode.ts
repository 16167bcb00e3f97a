/**
 * The comparison view (`compare=`): the same camera twice, the shown surface on the left half and
 * the compared one on the right (its own tessellator: src/app/compare-view.ts, rebuilt with the
 * left one), each with its own shadow pass, timing slot and error values; labels over the halves
 * name each surface and its max / RMS error. A right half whose surface refused the cage is
 * drawn as nothing (the stats and its label say why).
 */
import { compareLabel } from '../legend.ts';
import type { ErrorStats } from '../stats.ts';
import { isAcc, isExact, SURFACE_NAMES } from '../surfaces.ts';
import { ComputeMode, errorViewOnAcc } from './compute-mode.ts';
import type { Frame, ModeStats } from './mode.ts';
import type { ModeId } from './pick-mode.ts';

export class CompareMode extends ComputeMode {
  override readonly id: ModeId = 'compare';

  override frame(encoder: GPUCommandEncoder, f: Frame): void {
    const { params, errors } = this.host;
    const halves = this.host.compare;
    // The right half, rebuilt with the left one (and when it is new).
    const compare = this.host.compareGeometry();
    let compareRebuilt = false;
    if (compare?.output && (f.plan.stale || halves.dirty)) {
      compare.flatBaseline = params.flat;
      compare.encode(encoder, f.factors);
      halves.dirty = false;
      compareRebuilt = true;
      f.countBuild();
    }
    // The error passes, after the builds they measure: the left half's ACC surface (with an
    // error view, or to label it), the right half's.
    const main = isAcc(this.host.shown) ? this.host.tessellator : null;
    f.measure(encoder, [this.heatsMain() || compare ? main : null, compare && isAcc(compare.surface) ? compare : null], compareRebuilt);
    const mainHeat = this.heatsMain() ? (errors?.ready(main) ?? null) : null;
    f.bindHeat(mainHeat);
    const options = { ...f.options, heat: mainHeat ? f.heat : null };
    const renderer = f.renderer;
    if (!compare || !f.geometry.output) {
      renderer.render(encoder, f.target, f.view, options);
      return;
    }
    renderer.render(encoder, f.target, f.view, { ...options, region: { x0: 0, x1: 0.5, first: true, slot: 0 } });
    const cmpHeat = f.heat && isAcc(compare.surface) ? (errors?.ready(compare) ?? null) : null;
    renderer.setMesh(compare.output, this.host.closed);
    f.bindHeat(cmpHeat);
    renderer.render(encoder, f.target, f.view, {
      ...options,
      patchColours: options.patchColours && isExact(compare.surface),
      heat: cmpHeat ? f.heat : null,
      region: { x0: 0.5, x1: 1, first: false, slot: 1 },
    });
    renderer.setMesh(f.geometry.output, this.host.closed);
    f.bindHeat(mainHeat);
  }

  override heatsMain(): boolean {
    return errorViewOnAcc(this.host);
  }

  /** The colour bar also for an ACC scheme on the right half alone. */
  protected override showsHeat(): boolean {
    return this.heatsMain() || isAcc(this.host.params.compare);
  }

  override legend(): string | null {
    this.#showLabels(this.host.params.ui);
    return super.legend();
  }

  /** The labels over the two halves: each surface and its max / RMS error. */
  #showLabels(on: boolean): void {
    const host = this.host;
    host.compare.showLabels(on, () => {
      const stats = this.errorStats();
      const cmp = host.params.compare!;
      const refused = host.compare.refusal(host.model?.cage, cmp) !== null;
      return [
        compareLabel(host.shown, 'left', stats, host.params.errorView),
        refused ? `${SURFACE_NAMES[cmp]} · unavailable for this cage` : compareLabel(cmp, 'right', stats, host.params.errorView),
      ];
    });
  }

  override errorStats(): ErrorStats[] {
    const { model, errors, params, shown } = this.host;
    if (!model || !errors) return [];
    const unavailable = this.host.tables.refusal(model.cage);
    const out: ErrorStats[] = [];
    if (isAcc(shown)) out.push({ surface: shown, side: 'left', totals: errors.totals(this.host.tessellator), unavailable });
    const cmp = params.compare;
    if (cmp && isAcc(cmp) && this.host.compare.holds(model.cage))
      out.push({ surface: cmp, side: 'right', totals: errors.totals(this.host.compare.tessellator), unavailable });
    return out;
  }

  override stats(): ModeStats {
    const { params, model } = this.host;
    return { compare: { surface: params.compare!, refused: this.host.compare.refusal(model?.cage, params.compare) }, instanced: null };
  }

  override release(): void {
    this.#showLabels(false);
  }
}
