/**
 * The compute tessellator alone: its stored output (or the flat cage) drawn over the whole target.
 * The other modes build on it (error-mode.ts, instanced-mode.ts, split-mode.ts, compare-mode.ts).
 */
import type { DrawOptions } from '../../gpu/render/renderer.ts';
import { accPatchLegend, ccPatchLegend, heatLegend } from '../legend.ts';
import type { ErrorStats } from '../stats.ts';
import { isAcc, isExact } from '../surfaces.ts';
import type { Builds, DemoMode, Frame, ModeHost, ModeStats } from './mode.ts';
import type { ModeId } from './pick-mode.ts';

/** The legend of the compute tessellator's patch colours: an ACC scheme's patch kinds, else the
 * Catmull-Clark tables' triangle kinds. */
export function surfacePatchLegend(host: ModeHost): string {
  const accKinds = host.tessellator?.accPatchKinds;
  if (accKinds) return accPatchLegend(host.shown, accKinds);
  return ccPatchLegend(host.cc?.data.triKind ?? new Uint8Array());
}

/** An error view is asked for and the shown surface is an ACC scheme. */
export function errorViewOnAcc(host: ModeHost): boolean {
  return host.params.errorView !== 'off' && isAcc(host.shown);
}

export class ComputeMode implements DemoMode {
  readonly id: ModeId = 'compute';
  readonly instanced: boolean = false;
  protected readonly host: ModeHost;

  constructor(host: ModeHost) {
    this.host = host;
  }

  builds(): Builds {
    return { compute: true, instanced: null };
  }

  frame(encoder: GPUCommandEncoder, f: Frame): void {
    const main = this.heatsMain() ? this.host.tessellator : null;
    f.measure(encoder, [main, null], false);
    const heat = main ? (this.host.errors?.ready(main) ?? null) : null;
    f.bindHeat(heat);
    this.draw(encoder, f, { ...f.options, heat: heat ? f.heat : null });
  }

  /** The draw passes, after the builds and the error passes. */
  protected draw(encoder: GPUCommandEncoder, f: Frame, options: DrawOptions): void {
    f.renderer.render(encoder, f.target, f.view, options);
  }

  heatsMain(): boolean {
    return false;
  }

  patchColours(): boolean {
    const shown = this.host.shown;
    return this.host.params.patches && (isExact(shown) || isAcc(shown));
  }

  legend(): string | null {
    const params = this.host.params;
    if (params.errorView !== 'off' && this.showsHeat()) return heatLegend(params.errorView, this.host.errorRange, this.errorStats());
    return this.patchColours() ? this.patchLegend() : null;
  }

  /** The error colour bar is the legend (with an error view asked for). */
  protected showsHeat(): boolean {
    return this.heatsMain();
  }

  protected patchLegend(): string {
    return surfacePatchLegend(this.host);
  }

  errorStats(): ErrorStats[] {
    const { model, errors } = this.host;
    if (!model || !errors || !this.heatsMain()) return [];
    const unavailable = this.host.tables.refusal(model.cage);
    return [{ surface: this.host.shown, side: undefined, totals: errors.totals(this.host.tessellator), unavailable }];
  }

  stats(): ModeStats {
    return { compare: null, instanced: null };
  }

  release(): void {}
}
