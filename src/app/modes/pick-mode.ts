/**
 * Which of the demo's five modes draws (the factor mode, adaptive or fixed, is another thing:
 * params.ts `mode`): a pure function of what the URL and the panel ask for and what the shown
 * model allows. The demo holds the mode object it names (src/app/demo-scene.ts `mode`) and swaps
 * it when the answer changes (mode-switch.ts). DOM-free and GPU-free (tests/app/pick-mode.test.ts).
 */
import type { Shown } from '../controller.ts';
import type { DemoParams } from '../params.ts';
import { isAcc } from '../surfaces.ts';

/** The compute tessellator alone; the instanced tessellator alone; the split view (compute left,
 * instanced right); the comparison view (two surfaces side by side); the ACC error views. */
export type ModeId = 'compute' | 'instanced' | 'split' | 'compare' | 'error';

/** What is asked for (the URL, the panel). */
export type ModeAsk = Pick<DemoParams, 'tessellator' | 'split' | 'compare' | 'errorView'>;

/** What the shown model and the device allow. */
export interface ModeCaps {
  /** A model is shown (none before the first one loads). */
  model: boolean;
  /** The surface drawn: the one asked for, or Phong where that one refused the model
   * (src/app/controller.ts shownSurface), or the flat cage. */
  shown: Shown;
  /** The device reads storage buffers in the vertex stage, as the instanced tessellator must
   * (not in compatibility mode: src/gpu/render/renderer.ts vertexStorage). */
  vertexStorage: boolean;
}

/**
 * The mode that draws. In this order:
 * - no model yet, or the flat cage shown: the compute tessellator's picture (the cage's own
 *   faces); nothing else has a surface to draw;
 * - the instanced tessellator asked for (`tessellator=instanced`, or the split view whatever
 *   `tessellator` says) on a device with vertex-stage storage: the split view or the instanced
 *   tessellator alone (a cage its surface refuses is drawn as Phong by it: instanced-drawer.ts);
 *   without that storage the compute tessellator draws, with what else is asked;
 * - a comparison asked for: the comparison view (its right half empty, with the reason in the
 *   stats, where that surface refuses the cage: compare-view.ts);
 * - an error view asked for while an ACC scheme is shown: the error views;
 * - else the compute tessellator alone (an error view asked for on another surface draws nothing).
 */
export function pickMode(ask: ModeAsk, caps: ModeCaps): ModeId {
  if (!caps.model || caps.shown === 'cage') return 'compute';
  if ((ask.tessellator === 'instanced' || ask.split) && caps.vertexStorage) return ask.split ? 'split' : 'instanced';
  if (ask.compare !== null) return 'compare';
  if (ask.errorView !== 'off' && isAcc(caps.shown)) return 'error';
  return 'compute';
}
