/**
 * The ACC error views (`errorview=geometry|normal` on an ACC surface): the compute tessellator's
 * surface coloured by its error against the exact Catmull-Clark limit (the passes:
 * src/app/error-views.ts), the colour bar as the legend, max / RMS in the stats.
 */
import { ComputeMode, errorViewOnAcc } from './compute-mode.ts';
import type { ModeId } from './pick-mode.ts';

export class ErrorMode extends ComputeMode {
  override readonly id: ModeId = 'error';

  override heatsMain(): boolean {
    return errorViewOnAcc(this.host);
  }
}
