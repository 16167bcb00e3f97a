/**
 * The mode object of each id (pick-mode.ts), drawing with `host` (mode.ts).
 */
import { CompareMode } from './compare-mode.ts';
import { ComputeMode } from './compute-mode.ts';
import { ErrorMode } from './error-mode.ts';
import { InstancedMode } from './instanced-mode.ts';
import type { DemoMode, ModeHost } from './mode.ts';
import type { ModeId } from './pick-mode.ts';
import { SplitMode } from './split-mode.ts';

const MODES: Record<ModeId, new (host: ModeHost) => DemoMode> = {
  compute: ComputeMode,
  error: ErrorMode,
  instanced: InstancedMode,
  split: SplitMode,
  compare: CompareMode,
};

export function makeMode(id: ModeId, host: ModeHost): DemoMode {
  return new MODES[id](host);
}
