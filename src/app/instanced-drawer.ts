/**
 * The instanced tessellator as the demo draws it (`tessellator=instanced`, or the split view's
 * right half): the view made on first use and remade when its surface or displacement changes,
 * its last counts, and the cage that refused an ACC scheme (drawn as Phong, and why).
 */
import type { ShadingResources } from '../gpu/render/renderer.ts';
import type { Cage } from '../mesh/types.ts';
import { AccError } from '../subdiv/acc.ts';
import type { DisplacementSettings } from './displacement.ts';
import type { CageHeightMap } from './geometry.ts';
import { countsFromRecords, InstancedView, type InstancedCounts } from './instanced-view.ts';
import type { LoadedModel } from './models.ts';
import type { DemoParams } from './params.ts';
import { showToast } from './ui.ts';

export class InstancedDrawer {
  /** The view (null until first drawn, and after a device loss), and its last counts. */
  view: InstancedView | null = null;
  counts: InstancedCounts | null = null;
  #refused: { cage: Cage; surface: DemoParams['instSurface']; message: string } | null = null;

  deviceLost(): void {
    this.view = null;
    this.counts = null;
  }

  /** Why `surface` refused `cage` (null: it did not). */
  refusal(cage: Cage | undefined, surface: DemoParams['instSurface']): string | null {
    const r = this.#refused;
    return r && r.cage === cage && r.surface === surface ? r.message : null;
  }

  /** The view for `model` drawn as `want` (Phong where this cage refused that ACC scheme), with
   * its height map, displacement and flat shading: made, remade or re-uploaded as needed. */
  sync(
    device: GPUDevice,
    shading: ShadingResources,
    model: LoadedModel,
    want: DemoParams['instSurface'],
    height: CageHeightMap | null,
    displacement: DisplacementSettings,
    flatShading: boolean,
  ): InstancedView {
    const use = this.refusal(model.cage, want) !== null ? 'phong' : want;
    // A model with a height map: a view that displaces (src/gpu/instanced/displace-vertex.ts).
    let view = this.view;
    if (view && (view.surface !== use || view.displaced !== (height !== null))) {
      view.destroy();
      view = this.view = null;
    }
    view ??= this.view = new InstancedView(device, shading, use, height !== null);
    view.setDisplacement(displacement);
    if (view.cage !== model.cage || view.height !== height) {
      try {
        view.setCage(model.cage, height);
      } catch (e) {
        if (!(e instanceof AccError)) throw e;
        this.#refused = { cage: model.cage, surface: want, message: e.message };
        showToast(`${e.message}\n\nThe instanced tessellator draws Phong instead.`, {
          kind: 'info',
          title: `No ${want} patches for ${model.title}`,
          timeout: 10_000,
        });
        view.destroy();
        view = this.view = new InstancedView(device, shading, 'phong', height !== null);
        view.setDisplacement(displacement);
        view.setCage(model.cage, height);
      }
      this.counts = null;
    }
    view.tess.setFlatShading(flatShading);
    return view;
  }

  /** Test hook: the GPU's bucket draw records of the latest level pass, and the CPU's count for
   * static mode (null in dynamic mode). */
  async records(): Promise<{ gpu: number[]; cpu: number[] | null; mode: string; counts: InstancedCounts } | null> {
    const view = this.view;
    if (!view) return null;
    const lv = await view.tess.readLevels();
    const lp = view.lastLevels;
    const cpu = lp?.mode === 'static' ? view.cpuRecords(lp.level ?? 1) : null;
    return {
      gpu: Array.from(lv.records),
      cpu: cpu ? Array.from(cpu) : null,
      mode: lp?.mode ?? 'none',
      counts: countsFromRecords(lv.records, view.tess.patterns),
    };
  }
}
