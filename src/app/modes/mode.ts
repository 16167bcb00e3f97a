/**
 * The demo's modes behind one interface: the compute tessellator alone (compute-mode.ts), the
 * ACC error views (error-mode.ts), the instanced tessellator alone (instanced-mode.ts), the split
 * view (split-mode.ts) and the comparison view (compare-mode.ts). pick-mode.ts says which one
 * draws. A mode says what the frame builds, records its passes after the builds, and gives the
 * stats and the legend its part; the demo owns the builds, their staleness
 * (src/app/build-staleness.ts) and the readbacks (src/app/tessellation-demo.ts), and the scene
 * what the modes draw with (src/app/demo-scene.ts: the host below).
 */
import type { HeatView, AccHeatPass } from '../../gpu/acc/heat.ts';
import type { FactorParams } from '../../gpu/contract/tessellated-mesh.ts';
import type { DrawOptions, Renderer, View } from '../../gpu/render/renderer.ts';
import type { FramePlan } from '../build-staleness.ts';
import type { ArrivedTables, CcTables } from '../cc-tables.ts';
import type { CompareView } from '../compare-view.ts';
import type { Shown } from '../controller.ts';
import type { ErrorViews } from '../error-views.ts';
import type { GeometrySource, TessellatorGeometry } from '../geometry.ts';
import type { InstancedDrawer } from '../instanced-drawer.ts';
import type { InstancedView } from '../instanced-view.ts';
import type { LoadedModel } from '../models.ts';
import type { DemoParams } from '../params.ts';
import type { ErrorStats, StatsInput } from '../stats.ts';
import type { ModeId } from './pick-mode.ts';

/** What a mode draws with: the scene's current objects (read at each call: a device loss or a
 * new model replaces them). */
export interface ModeHost {
  readonly params: DemoParams;
  /** The surface drawn (src/app/controller.ts shownSurface). */
  readonly shown: Shown;
  readonly model: LoadedModel | null;
  /** The compute tessellator of the shown surface (null while the flat cage is drawn). */
  readonly tessellator: TessellatorGeometry | null;
  /** The shown model's Catmull-Clark tables, if it has them. */
  readonly cc: CcTables | null;
  /** The same tables once arrived (the error views' exact reference). */
  readonly tables: ArrivedTables;
  readonly instanced: InstancedDrawer;
  readonly compare: CompareView;
  /** The error views' passes (null without a device). */
  readonly errors: ErrorViews | null;
  /** The error colour bar's top, in the view's unit. */
  readonly errorRange: number;
  /** The cage is closed (the renderer culls back faces). */
  readonly closed: boolean;
  /** The comparison's tessellator with the model's cage on it (src/app/compare-view.ts prepare). */
  compareGeometry(): TessellatorGeometry | null;
}

/** What a frame builds before the mode records its passes (src/app/build-staleness.ts FrameInputs). */
export interface Builds {
  /** The compute tessellator's output (drawn alone, or in a half). */
  compute: boolean;
  /** The instanced tessellator whose level pass (or owed copy) the frame encodes, if it draws. */
  instanced: InstancedView | null;
}

/** One frame, as the demo set it up and built it (src/app/tessellation-demo.ts onFrame). */
export interface Frame {
  readonly renderer: Renderer;
  readonly target: GPUTexture;
  /** What is drawn by the compute tessellator's side: its output, or the flat cage. */
  readonly geometry: GeometrySource;
  readonly factors: FactorParams;
  /** This frame's builds (the comparison rebuilds its right half with a stale left one). */
  readonly plan: FramePlan;
  readonly view: View;
  /** The draw options of the whole target, without heat values. */
  readonly options: DrawOptions;
  /** The error view asked for and its colour bar's top (null: off). */
  readonly heat: { view: HeatView; range: number } | null;
  /** The error passes of `measured` (the left or only surface, the comparison's right half),
   * after the builds they measure; the passes of anything else go. */
  measure(
    encoder: GPUCommandEncoder,
    measured: readonly [TessellatorGeometry | null, TessellatorGeometry | null],
    compareRebuilt: boolean,
  ): void;
  /** Hand the renderer the values of `pass` (null: none). */
  bindHeat(pass: AccHeatPass | null): void;
  /** One more build for the stats' count (the comparison's right half). */
  countBuild(): void;
}

/** What a mode gives the stats panel (src/app/stats.ts). */
export type ModeStats = Required<Pick<StatsInput, 'compare' | 'instanced'>>;

export interface DemoMode {
  readonly id: ModeId;
  /** The instanced tessellator draws (alone, or the split view's right half): its counts are read
   * back, and the stats' other factor mode (a compute build) is not counted. */
  readonly instanced: boolean;
  /** What this frame builds. */
  builds(): Builds;
  /** Record the passes after the builds: the comparison's build, the error passes, the draws. */
  frame(encoder: GPUCommandEncoder, frame: Frame): void;
  /** The error views colour the compute tessellator's surface (alone, or the left half). */
  heatsMain(): boolean;
  /** The surface is tinted by its patches (the panel's toggle, where there are patches). */
  patchColours(): boolean;
  /** The legend's HTML (patch colours or the error colour bar), null: hidden. The comparison's
   * labels over its halves are updated with it. */
  legend(): string | null;
  /** The error views' rows of the stats (the measured surfaces' max / RMS). */
  errorStats(): ErrorStats[];
  /** The stats' rows of the comparison and the instanced tessellator. */
  stats(): ModeStats;
  /** Another mode draws now: let go of what only this one shows. */
  release(): void;
}
