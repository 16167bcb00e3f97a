/**
 * The split view (`split=1`): the same camera twice, the compute tessellator's stored output on
 * the left half and the instanced tessellator on the right, each with its own shadow pass and
 * timing slot. An error view colours the left half's ACC surface.
 */
import type { DrawOptions } from '../../gpu/render/renderer.ts';
import { SideLabels } from '../side-labels.ts';
import { SURFACE_NAMES } from '../surfaces.ts';
import { errorViewOnAcc, surfacePatchLegend } from './compute-mode.ts';
import { InstancedMode, instancedStats } from './instanced-mode.ts';
import type { Builds, Frame, ModeStats } from './mode.ts';
import type { ModeId } from './pick-mode.ts';

export class SplitMode extends InstancedMode {
  override readonly id: ModeId = 'split';

  override builds(): Builds {
    return { compute: true, instanced: this.host.instanced.view };
  }

  protected override draw(encoder: GPUCommandEncoder, f: Frame, options: DrawOptions): void {
    const view = this.host.instanced.view;
    if (!view) {
      super.draw(encoder, f, options);
      return;
    }
    const renderer = f.renderer;
    renderer.setDrawer(null);
    renderer.render(encoder, f.target, f.view, { ...options, region: { x0: 0, x1: 0.5, first: true, slot: 0 } });
    renderer.setDrawer(view.tess);
    renderer.render(encoder, f.target, f.view, { ...options, region: { x0: 0.5, x1: 1, first: false, slot: 1 } });
    renderer.setDrawer(null);
  }

  override heatsMain(): boolean {
    return errorViewOnAcc(this.host);
  }

  /** The compute tessellator's patch colours (the left half's). */
  protected override patchLegend(): string {
    return surfacePatchLegend(this.host);
  }

  override stats(): ModeStats {
    return { compare: null, instanced: instancedStats(this.host, true) };
  }

  /** The labels over the halves (which tessellator draws which), updated with the legend. */
  override legend(): string | null {
    const host = this.host;
    splitLabels.show(host.params.ui, () => {
      const s = instancedStats(host, true);
      const inst = s?.surface && s.surface in SURFACE_NAMES ? SURFACE_NAMES[s.surface as keyof typeof SURFACE_NAMES] : 'Phong';
      return [`compute · ${SURFACE_NAMES[host.shown] ?? host.shown} · stored mesh`, `instanced · ${inst} · ${s?.setting ?? ''}`];
    });
    return super.legend();
  }

  override release(): void {
    splitLabels.show(false, () => ['', '']);
    super.release();
  }
}

/** One pair for the page (the split view is one at a time). */
const splitLabels = new SideLabels('split');
