/**
 * The instanced tessellator alone (`tessellator=instanced`): it evaluates the surface in every
 * draw pass (src/app/instanced-view.ts), handed to the renderer at upload (src/app/demo-scene.ts
 * syncDrawer); its level pass is the frame's build. Its patch colours are its domains' (quads,
 * triangles) on any surface. Until its view is made, the compute tessellator draws.
 */
import { instancedPatchLegend } from '../legend.ts';
import { isAcc, isExact } from '../surfaces.ts';
import { ComputeMode } from './compute-mode.ts';
import type { Builds, ModeHost, ModeStats } from './mode.ts';
import type { ModeId } from './pick-mode.ts';

/** The stats' rows of the instanced tessellator (`split`: it draws the split view's right half). */
export function instancedStats(host: ModeHost, split: boolean): ModeStats['instanced'] {
  const { params, instanced } = host;
  return {
    split,
    surface: instanced.view?.surface ?? 'phong',
    asked: params.instSurface,
    fallback: instanced.refusal(host.model?.cage, params.instSurface),
    counts: instanced.counts,
    setting: params.mode === 'fixed' ? `static level ${params.level}` : `dynamic LOD ${params.lod}`,
  };
}

export class InstancedMode extends ComputeMode {
  override readonly id: ModeId = 'instanced';
  override readonly instanced: boolean = true;

  override builds(): Builds {
    const view = this.host.instanced.view;
    return { compute: view === null, instanced: view };
  }

  override patchColours(): boolean {
    return this.host.params.patches;
  }

  protected override patchLegend(): string {
    const view = this.host.instanced.view;
    if (!view) return super.patchLegend();
    return instancedPatchLegend(view.patchColourCounts(), isAcc(view.surface) || isExact(view.surface));
  }

  override stats(): ModeStats {
    return { compare: null, instanced: instancedStats(this.host, false) };
  }
}
