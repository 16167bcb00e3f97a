/**
 * The demo page: a cage, tessellated on the GPU (the Catmull-Clark limit surface, or Phong
 * tessellation), drawn lit and shadowed with optional wireframe, cage overlay and patch colours.
 * The geometry is rebuilt only when the model, the factors or (in adaptive mode) the camera
 * change; every other frame draws the stored buffers again. The Catmull-Clark data (topology only)
 * is prepared on the CPU once per model (cc-tables.ts); the GPU builds the patches every frame.
 *
 * What is shown (model, surface, its data) and the flow that changes it live in controller.ts;
 * this file is the page: the canvas, the GPU objects, the panel, the stats and the messages.
 */
import GUI from 'lil-gui';
import { isClosed } from '../mesh/index.ts';
import { mat4 } from 'gl-matrix';
import {
  boundsOf,
  cameraMatrices,
  transformBounds,
  transformPoint,
  upAxisMatrix,
  type Bounds,
  type OrbitCamera,
} from '../gpu/render/camera.ts';
import { uploadCageLines, type CageLines } from '../gpu/render/cage-mesh.ts';
import { PATCH_COLOURS, Renderer } from '../gpu/render/renderer.ts';
import type { FactorParams } from '../gpu/contract/tessellated-mesh.ts';
import { clampMessages, wantedOutputLimits } from './limits.ts';
import type { LimitName } from '../gpu/device/device.ts';
import { CcTableCache, type CcTables } from './cc-tables.ts';
import { DemoController, type DemoPorts, type Shown } from './controller.ts';
import { DemoBase } from './demo-base.ts';
import { CountsReader, type MeshCounts } from './counts.ts';
import { CageGeometry, TessellatorGeometry, type GeometrySource, type TessSurface } from './geometry.ts';
import { isAccSurface } from '../gpu/tess/passes.ts';
import { BUILTIN_MODELS, DEFAULT_MODEL, loadModelFromFile, loadModelFromUrl, modelUrl, type LoadedModel } from './models.ts';
import {
  DSCALE_RANGE,
  ERR_RANGE,
  FACTOR_RANGE,
  formatParams,
  isModelUrl,
  LEVEL_CHOICES,
  LOD_RANGE,
  parseParams,
  type DemoParams,
} from './params.ts';
import { countsFromRecords, InstancedView, type InstancedCounts } from './instanced-view.ts';
import { factorRuleLevels, type LevelParams } from '../gpu/instanced/instanced-options.ts';
import { AccError } from '../subdiv/acc.ts';
import { HEAT_DEFAULT_RANGE, HEAT_RAMP, type HeatView } from '../gpu/acc/heat.ts';
import type { Cage } from '../mesh/types.ts';
import type { CatmullClarkData } from '../gpu/cc/build.ts';
import { ErrorViews } from './error-views.ts';
import { ACC_SURFACES, COMPARE_SURFACES, type CompareSurface } from './params.ts';
import { degrees, percentOfDiagonal, type ErrorStats } from './stats.ts';
import { errorMessage } from './controller.ts';
import { OtherModeProbe } from './other-mode.ts';
import { renderStats } from './stats.ts';
import { TrailingThrottle } from './throttle.ts';
import { setLoading, setPageState, showToast } from './ui.ts';
import { builtinHeight, decodeHeightImage, defaultHeightScale, fetchBuiltinHeight, type HeightEntry } from './displacement.ts';
import { findEdge, uvCoverage, uvSeams } from '../mesh/index.ts';

/** The surfaces by their names in the panel and in messages. */
const SURFACE_NAMES: Record<DemoParams['surface'], string> = {
  'catmull-clark': 'Catmull-Clark',
  phong: 'Phong',
  'bezier-acc': 'Bezier ACC',
  'gregory-acc': 'Gregory ACC',
  'pm-acc': 'Pm ACC',
  cage: 'flat cage',
};

/** An ACC scheme (the surfaces the error views measure). */
function isAcc(surface: string | null | undefined): surface is (typeof ACC_SURFACES)[number] {
  return (ACC_SURFACES as readonly string[]).includes(surface ?? '');
}

/** Turntable speed, radians per second. */
const SPIN_SPEED = 0.35;

type CameraParams = Partial<Pick<DemoParams, 'yaw' | 'pitch' | 'dist'>>;

/** What a model request carries to the page: the first view, and what the cage picker shows. */
interface Placement {
  camera?: CameraParams;
  pick: string;
}

class TessellationDemo extends DemoBase {
  params: DemoParams;
  /** The model, its surface data and the surface drawn, and the one flow that changes them. */
  readonly controller: DemoController<LoadedModel, CcTables, Placement>;
  panel: Panel | null = null;
  /** The model's bounds in world space, and its model-to-world rotation (up axis to +Y). */
  #bounds: Bounds | null = null;
  #modelMatrix = upAxisMatrix('z') as Float32Array;

  #renderer: Renderer | null = null;
  /** The tessellator of the surface drawn (one at a time: each holds big output buffers), and
   * the flat cage (for before/after). */
  #tess: Partial<Record<TessSurface, TessellatorGeometry>> = {};
  /** Height maps by cage: the project's displaced models' (fetched with the OBJ) and PNGs the
   * user dropped (src/app/displacement.ts). */
  #heights = new WeakMap<LoadedModel['cage'], HeightEntry>();
  #flat: CageGeometry | null = null;
  #cageLines: CageLines | null = null;
  #counts: CountsReader | null = null;
  /** The instanced tessellator (`tessellator=instanced`), made on first use, and its last counts. */
  #instanced: InstancedView | null = null;
  #instancedCounts: InstancedCounts | null = null;
  /** The cage that refused an ACC scheme (the instanced tessellator draws Phong for it), and why. */
  #instancedRefused: { cage: LoadedModel['cage']; surface: DemoParams['instSurface']; message: string } | null = null;

  /** Catmull-Clark data per cage (topology only, cached): the controller's surface data. */
  readonly #ccTables = new CcTableCache();
  /** The same data once it has arrived (or why it cannot), for the error views' exact reference
   * and a Catmull-Clark comparison, which the controller does not prepare it for. */
  readonly #tablesDone = new WeakMap<Cage, CcTables | string>();
  readonly #tablesAsked = new WeakSet<Cage>();

  /** The ACC error views' passes (src/app/error-views.ts), made with the device. */
  #errors: ErrorViews | null = null;
  /** The error view's values the renderer has bound (their pass), to bind again only on change. */
  #boundHeat: object | null = null;
  /** The comparison view's right half (`compare=`): its own tessellator, the cage it holds, and
   * the cage/surface it refused (drawn as nothing, with the reason in the stats). */
  #compare: TessellatorGeometry | null = null;
  #compareCage: Cage | null = null;
  #compareDirty = true;
  #compareRefused: { cage: Cage; surface: CompareSurface; message: string } | null = null;
  #compareLabels: [HTMLElement, HTMLElement] | null = null;
  /** Whether the model's cage is closed (the renderer culls back faces). */
  #closed = false;

  /** The other factor mode's counts (an extra build, then the drawn one again), and when to redo it. */
  readonly #otherMode = new OtherModeProbe({
    now: () => performance.now(),
    later: (ms, fn) => window.setTimeout(fn, ms),
    redraw: () => this.requestFrame(),
    changed: () => this.updateStats(true),
  });
  #otherReader: CountsReader | null = null;
  /** The factors of this frame's camera, and of the build the output holds now. */
  #frameFactors: FactorParams | null = null;
  #builtFactors: FactorParams | null = null;

  #lastCounts: MeshCounts | null = null;
  /** GPU milliseconds of the last rebuild's passes, and of the last frame's draw passes. */
  #tessTimes: Record<string, number> = {};
  #drawTimes: Record<string, number> = {};
  #rebuilds = 0;
  #geometryDirty = true;
  /** A build's counts still to be copied for reading back. */
  #countsOwed = false;
  #rebuiltThisFrame = false;
  #tessTimingInFlight = false;
  /** The stats panel is redrawn at most every 250 ms (see updateStats). */
  readonly #statsThrottle = new TrailingThrottle(() => this.#renderStats(), 250, {
    now: () => performance.now(),
    setTimeout: (fn, ms) => window.setTimeout(fn, ms),
    clearTimeout: (id) => window.clearTimeout(id),
  });
  #firstFrameShown = false;
  /** Test hook (window.tessellab.holdPreparation): surface data waits while held, as slow data would. */
  #hold: { held: boolean; promise: Promise<void>; release(): void } = { held: false, promise: Promise.resolve(), release() {} };

  holdPreparation(hold: boolean): void {
    if (hold === this.#hold.held) return;
    if (!hold) {
      this.#hold.release();
      this.#hold = { held: false, promise: Promise.resolve(), release() {} };
      return;
    }
    let release!: () => void;
    const promise = new Promise<void>((r) => (release = r));
    this.#hold = { held: true, promise, release };
  }

  constructor(canvas: HTMLCanvasElement, params: DemoParams) {
    super(canvas, { frozenTime: params.t });
    this.params = params;
    this.controller = new DemoController(this.#ports(), params.surface);
  }

  /** The page's side of the controller. */
  #ports(): DemoPorts<LoadedModel, CcTables, Placement> {
    return {
      prepareSurface: (model) => this.#hold.promise.then(() => this.#ccTables.get(model.cage)),
      surfaceReady: (model) => !this.#hold.held && this.#ccTables.has(model.cage),
      upload: (model, surface, data) => this.#upload(model, surface, data),
      loading: (message) => setLoading(message),
      preparing: () => this.updateStats(true),
      failed: (title, message, kept) => {
        showToast(message, { kind: 'error', title });
        if (!kept) setPageState('error');
      },
      fellBack: (model, reason, surface) =>
        showToast(`${reason}\n\nShowing the Phong surface instead.`, {
          kind: 'info',
          title: `No ${SURFACE_NAMES[surface] ?? surface} surface for ${model.title}`,
          timeout: 10_000,
        }),
      shown: (model, previous, placement) => {
        if (model !== previous) {
          for (const w of model.warnings.slice(0, 3)) console.info(`${model.title}: ${w.line ? `line ${w.line}: ` : ''}${w.message}`);
          this.placeModel(placement?.camera);
        }
        if (placement) this.panel?.showPicked(placement.pick);
        this.#lastCounts = null;
        this.#tessTimes = {};
        this.updateLegend();
        this.invalidateGeometry();
        // The first model's message stays until its first frame is on screen (onAfterSubmit).
        if (previous) setLoading(null);
        this.updateStats(true);
      },
    };
  }

  get model(): LoadedModel | null {
    return this.controller.model;
  }

  /** The shown model's Catmull-Clark tables (kept while another surface is drawn), or null. */
  get cc(): CcTables | null {
    return this.controller.data;
  }

  /** The output buffers the capacity asks for (positions: 12 bytes a vertex, indices: 12 a triangle). */
  protected override wantedLimits(): Partial<Record<LimitName, number>> {
    return wantedOutputLimits(this.#requestedCapacity);
  }

  get #requestedCapacity(): number {
    return Math.round(this.params.capacity * 1e6);
  }

  /** What the device's limits cut (said once per device, and kept in the stats). */
  #clamps: string[] = [];

  #reportClamps(): void {
    const clamps = clampMessages(this.gpu.clamps, this.gpu.device.limits, this.#requestedCapacity);
    const before = this.#clamps.join('\n');
    this.#clamps = clamps;
    // Once per device, and again only if a new device clamps differently.
    if (clamps.length && clamps.join('\n') !== before) {
      showToast(clamps.join('\n'), { kind: 'info', title: "Clamped to this GPU's limits", timeout: 10_000 });
    }
  }

  protected override async onInit(): Promise<void> {
    const device = this.gpu.device;
    this.#reportClamps();
    this.#renderer = Renderer.create(device, { colorFormat: this.renderFormat, timestamps: this.gpu.timestamps });
    this.#flat = new CageGeometry(device);
    this.#counts = new CountsReader(device);
    this.#otherReader = new CountsReader(device);
    this.#errors = new ErrorViews(device);
    this.#boundHeat = null;
    this.#otherMode.reset();
    // After a device loss: upload the current model to the new device.
    this.controller.reupload();
  }

  protected override onDeviceLost(): void {
    this.#renderer = null;
    this.#tess = {};
    this.#flat = null;
    this.#cageLines = null;
    this.#counts = null;
    this.#instanced = null;
    this.#instancedCounts = null;
    this.#otherReader = null;
    this.#frameFactors = this.#builtFactors = null;
    this.#errors = null;
    this.#boundHeat = null;
    this.#compare = null;
    this.#compareCage = null;
  }

  /** The Catmull-Clark tables of `cage` if they have arrived; else asks for them (a frame is
   * requested when they come) and answers null. A refused cage answers its reason. */
  #tablesFor(cage: Cage): CatmullClarkData | string | null {
    const done = this.#tablesDone.get(cage);
    if (done !== undefined) return typeof done === 'string' ? done : done.data;
    if (!this.#tablesAsked.has(cage)) {
      this.#tablesAsked.add(cage);
      this.#ccTables
        .get(cage)
        .then(
          (t) => this.#tablesDone.set(cage, t),
          (e: unknown) => this.#tablesDone.set(cage, errorMessage(e)),
        )
        .finally(() => {
          // The error passes start with the next frame; a Catmull-Clark comparison builds then.
          this.#compareDirty = true;
          this.requestFrame();
          this.updateStats(true);
        });
    }
    return null;
  }

  /** The error views draw: asked for, and an ACC scheme is drawn by the compute tessellator. */
  get errorViewActive(): boolean {
    return (
      this.params.errorView !== 'off' && isAcc(this.shownSurface) && this.model !== null && (!this.instancedActive || this.splitActive)
    );
  }

  /** The comparison view: asked for, a surface is shown, and the instanced tessellator is off
   * (its split view is the other use of the two halves). */
  get compareActive(): boolean {
    return this.params.compare !== null && this.shownSurface !== 'cage' && this.model !== null && !this.instancedActive;
  }

  /** The colour bar's top, in the view's unit. */
  get errorRange(): number {
    const view = this.params.errorView === 'normal' ? 'normal' : 'geometry';
    return this.params.errRange ?? HEAT_DEFAULT_RANGE[view];
  }

  /** The comparison's surface (the panel, the URL); null: off. */
  setCompare(surface: CompareSurface | null): void {
    this.params.compare = surface;
    this.#compare?.destroy();
    this.#compare = null;
    this.#compareCage = null;
    this.#compareDirty = true;
    this.updateLegend();
    this.invalidateGeometry();
    this.updateStats(true);
  }

  /** The error view and its range (the panel, the URL). */
  setErrorView(view: DemoParams['errorView'], range: number | null): void {
    this.params.errorView = view;
    this.params.errRange = range;
    this.updateLegend();
    this.invalidateGeometry();
    this.updateStats(true);
  }

  /** The comparison's tessellator with the model's cage on it, made or re-uploaded as needed;
   * null while its data is not there, or when it refused the cage. */
  #compareGeometry(): TessellatorGeometry | null {
    const model = this.model,
      want = this.params.compare;
    if (!model || !want) return null;
    const refused = this.#compareRefused;
    if (refused && refused.cage === model.cage && refused.surface === want) return null;
    let cc: CatmullClarkData | undefined;
    if (want === 'catmull-clark') {
      const t = this.#tablesFor(model.cage);
      if (t === null) return null;
      if (typeof t === 'string') {
        this.#compareRefused = { cage: model.cage, surface: want, message: t };
        return null;
      }
      cc = t;
    }
    if (this.#compare && this.#compare.surface !== want) {
      this.#compare.destroy();
      this.#compare = null;
    }
    this.#compare ??= new TessellatorGeometry(this.gpu.device, this.params.capacity * 1e6, want);
    if (this.#compareCage !== model.cage) {
      this.#compareCage = null;
      try {
        // Displaced as the left half is (the error views measure the surfaces before displacement).
        this.#compare.setCage(model.cage, cc, this.#heights.get(model.cage)?.height ?? null);
        const entry = this.#heights.get(model.cage);
        this.#compare.setDisplacement({
          enabled: this.params.disp && entry !== undefined,
          scale: (entry?.scale ?? 0) * this.params.dscale,
          midLevel: entry?.midLevel ?? 0.5,
        });
      } catch (e) {
        this.#compareRefused = { cage: model.cage, surface: want, message: errorMessage(e) };
        showToast(errorMessage(e), {
          kind: 'info',
          title: `No ${SURFACE_NAMES[want]} surface to compare for ${model.title}`,
          timeout: 10_000,
        });
        return null;
      }
      this.#compareCage = model.cage;
      this.#compareDirty = true;
    }
    return this.#compare;
  }

  /** The error view's rows of the stats: the main surface and the comparison's right half. */
  #errorStats(): ErrorStats[] {
    const model = this.model,
      errors = this.#errors;
    if (!model || !errors || (this.params.errorView === 'off' && !this.compareActive)) return [];
    const tables = this.#tablesDone.get(model.cage);
    const unavailable = typeof tables === 'string' ? tables : null;
    const out: ErrorStats[] = [];
    const compare = this.compareActive;
    const main = this.geometry instanceof TessellatorGeometry ? this.geometry : null;
    if (isAcc(this.shownSurface) && (this.errorViewActive || compare))
      out.push({ surface: this.shownSurface, side: compare ? 'left' : undefined, totals: errors.totals(main), unavailable });
    const cmp = compare ? this.params.compare : null;
    if (cmp && isAcc(cmp) && this.#compare && this.#compareCage === model.cage)
      out.push({ surface: cmp, side: 'right', totals: errors.totals(this.#compare), unavailable });
    return out;
  }

  /** The comparison's labels over the two halves: each surface and its max / RMS error. */
  #updateCompareLabels(): void {
    const on = this.compareActive && this.params.ui;
    if (!on && !this.#compareLabels) return;
    if (!this.#compareLabels) {
      const make = (side: 'left' | 'right') => {
        const el = document.createElement('div');
        el.className = `compare-label ${side}`;
        el.dataset.testid = `compare-${side}`;
        document.body.append(el);
        return el;
      };
      this.#compareLabels = [make('left'), make('right')];
    }
    const [left, right] = this.#compareLabels;
    left.hidden = right.hidden = !on;
    if (!on) return;
    const stats = this.#errorStats();
    const text = (surface: string, side: 'left' | 'right') => {
      const name = SURFACE_NAMES[surface as DemoParams['surface']] ?? surface;
      const e = stats.find((x) => x.side === side);
      if (!isAcc(surface)) return surface === 'catmull-clark' ? `${name} · exact` : name;
      if (!e?.totals) return `${name} · ${e?.unavailable ? 'no error view' : 'measuring…'}`;
      const t = e.totals;
      return this.params.errorView === 'normal'
        ? `${name} · max ${degrees(t.maxAngle)} · RMS ${degrees(t.rmsAngle)}`
        : `${name} · max ${percentOfDiagonal(t.maxDistance)} · RMS ${percentOfDiagonal(t.rmsDistance)}`;
    };
    left.textContent = text(this.shownSurface, 'left');
    const cmp = this.params.compare!;
    const refused = this.#compareRefused;
    right.textContent =
      refused && refused.cage === this.model?.cage && refused.surface === cmp
        ? `${SURFACE_NAMES[cmp]} · unavailable for this cage`
        : text(cmp, 'right');
  }

  /** The surface drawn now: the one asked for, but Phong where the model has no Catmull-Clark
   * tables (refused, or still being built). */
  get shownSurface(): Shown {
    return this.controller.shownSurface;
  }

  /** What is drawn now: the tessellated surface or the flat cage. */
  get geometry(): GeometrySource | null {
    return this.#geometryFor(this.shownSurface);
  }

  #geometryFor(surface: Shown): GeometrySource | null {
    return surface === 'cage' ? this.#flat : (this.#tess[surface] ?? null);
  }

  /** The instanced tessellator draws, alone or in the split view (asked for, and a surface
   * rather than the flat cage is shown). */
  get instancedActive(): boolean {
    return (
      (this.params.tessellator === 'instanced' || this.params.split) &&
      this.shownSurface !== 'cage' &&
      this.model !== null &&
      (this.#renderer?.vertexStorage ?? true)
    );
  }

  /** The split view: compute on the left half, instanced on the right, same cage and camera. */
  get splitActive(): boolean {
    return this.params.split && this.instancedActive;
  }

  /** Hand the renderer the instanced tessellator (the model's patches uploaded) or take it back,
   * for `model` drawn as `surface` (at upload: before the controller commits them). */
  #syncDrawer(model: LoadedModel | null, surface: Shown): void {
    const renderer = this.#renderer;
    if (!renderer) return;
    renderer.setDrawer(null);
    if ((this.params.tessellator !== 'instanced' && !this.params.split) || surface === 'cage' || !model) return;
    // It evaluates in the vertex stage, from storage: not on a device without vertex-stage storage
    // (compatibility mode; the clamp message says so once), where the compute tessellator draws.
    if (!renderer.vertexStorage) return;
    // Its surface: the one asked for, or Phong where this cage refused that ACC scheme.
    const want = this.params.instSurface;
    const refused = this.#instancedRefused;
    const use = refused && refused.cage === model.cage && refused.surface === want ? 'phong' : want;
    // A model with a height map: a view that displaces (src/gpu/instanced/displace-vertex.ts).
    const height = this.#heights.get(model.cage)?.height ?? null;
    let view = this.#instanced;
    if (view && (view.surface !== use || view.displaced !== (height !== null))) {
      view.destroy();
      view = this.#instanced = null;
    }
    view ??= this.#instanced = new InstancedView(this.gpu.device, renderer.shadingResources, use, height !== null);
    view.setDisplacement(this.#displacementSettings(model));
    if (view.cage !== model.cage || view.height !== height) {
      try {
        view.setCage(model.cage, height);
      } catch (e) {
        if (!(e instanceof AccError)) throw e;
        this.#instancedRefused = { cage: model.cage, surface: want, message: e.message };
        showToast(`${e.message}\n\nThe instanced tessellator draws Phong instead.`, {
          kind: 'info',
          title: `No ${want} patches for ${model.title}`,
          timeout: 10_000,
        });
        view.destroy();
        view = this.#instanced = new InstancedView(this.gpu.device, renderer.shadingResources, 'phong', height !== null);
        view.setDisplacement(this.#displacementSettings(model));
        view.setCage(model.cage, height);
      }
      this.#instancedCounts = null;
    }
    view.tess.setFlatShading(this.params.flatShade);
    // The split view hands it over per half, in onFrame.
    if (!this.params.split) renderer.setDrawer(view.tess);
  }

  /** The instanced tessellator's flat shading (the panel, the URL). */
  setInstancedFlat(flat: boolean): void {
    this.params.flatShade = flat;
    this.#instanced?.tess.setFlatShading(flat);
    this.requestFrame();
  }

  /** The instanced tessellator's surface (the panel, the URL): Phong or an ACC scheme. */
  setInstancedSurface(surface: DemoParams['instSurface']): void {
    this.params.instSurface = surface;
    this.#syncDrawer(this.model, this.shownSurface);
    this.updateLegend();
    this.invalidateGeometry();
    this.updateStats(true);
  }

  /** Turn the split view on or off (the panel, the URL). */
  setSplit(split: boolean): void {
    this.params.split = split;
    this.#syncDrawer(this.model, this.shownSurface);
    this.updateLegend();
    this.invalidateGeometry();
    this.updateStats(true);
  }

  /** Switch tessellators (the panel, the URL): the same model, camera and settings. */
  setTessellator(kind: DemoParams['tessellator']): void {
    this.params.tessellator = kind;
    this.#syncDrawer(this.model, this.shownSurface);
    this.updateLegend();
    this.invalidateGeometry();
    this.updateStats(true);
  }

  /** The instanced tessellator's level parameters for this frame: fixed → every patch at the
   * static level; adaptive → each edge's level by the compute tessellator's factor rule at the
   * same camera and LOD scale (model space), rounded up to a power of two. */
  #instancedLevels(factors: FactorParams): LevelParams {
    if (this.params.mode === 'fixed') return { mode: 'static', level: this.params.level };
    return factorRuleLevels(factors);
  }

  /** Test hook: the GPU's bucket draw records of the latest level pass, and the CPU's count for
   * static mode (null in dynamic mode). */
  async instancedRecords(): Promise<{ gpu: number[]; cpu: number[] | null; mode: string; counts: InstancedCounts } | null> {
    const view = this.#instanced;
    if (!view || !this.instancedActive) return null;
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

  /** The tessellator for `surface`, created on first use (the other one is freed). */
  #tessellator(surface: TessSurface): TessellatorGeometry {
    let tess = this.#tess[surface];
    if (!tess) {
      for (const other of Object.values(this.#tess)) other.destroy();
      tess = new TessellatorGeometry(this.gpu.device, this.params.capacity * 1e6, surface);
      this.#tess = { [surface]: tess };
    }
    return tess;
  }

  /** Patch colours are on and there are patches to colour. */
  get patchColours(): boolean {
    // The instanced tessellator colours its patches by domain (quad, triangle) on any surface.
    return (
      this.params.patches &&
      (this.shownSurface === 'catmull-clark' || isAccSurface(this.shownSurface as TessSurface) || this.instancedActive)
    );
  }

  /** The legend of the patch colours, with each kind's share of the cage's triangles. */
  updateLegend(): void {
    const legend = document.getElementById('legend');
    if (!legend) return;
    this.#updateCompareLabels();
    if (this.params.errorView !== 'off' && (this.errorViewActive || (this.compareActive && isAcc(this.params.compare)))) {
      legend.hidden = false;
      legend.innerHTML = this.#heatLegend(this.params.errorView);
      return;
    }
    legend.hidden = !this.patchColours;
    if (legend.hidden) return;
    const kinds = this.cc?.data.triKind ?? new Uint8Array();
    const count = [0, 0, 0, 0];
    for (const k of kinds) count[k]++;
    const inst = this.instancedActive && !this.splitActive ? this.#instanced : null;
    const hex = (c: readonly number[]) =>
      `#${c
        .map((x) =>
          Math.round(x * 255)
            .toString(16)
            .padStart(2, '0'),
        )
        .join('')}`;
    if (inst) {
      // wgsl/instanced/surface-*.wgsl patchColourIndex: regular, irregular quad (ACC only), triangle.
      const n = inst.patchColourCounts();
      const entry = (k: number, name: string) =>
        `<li><span class="swatch" style="background:${hex(PATCH_COLOURS[k].srgb)}"></span>${name} <span class="muted">${n[k]}</span></li>`;
      const acc = inst.surface !== 'phong';
      legend.innerHTML = `<strong>Patches (instanced)</strong><ul>${entry(0, acc ? 'regular' : 'quad')}${acc ? entry(1, 'irregular quad') : ''}${entry(2, 'triangle')}</ul>`;
      return;
    }
    const shown = this.shownSurface;
    const accKinds = shown !== 'cage' ? this.#tess[shown]?.accPatchKinds : null;
    if (accKinds) {
      // An ACC surface (the sample's "show irregular patches"): regular, irregular quad, triangle.
      const n = [0, 0, 0];
      for (const k of accKinds) n[k]++;
      legend.innerHTML = `<strong>Patches (${SURFACE_NAMES[shown]})</strong><ul>${[0, 1, 2]
        .map(
          (k) =>
            `<li><span class="swatch" style="background:${hex(PATCH_COLOURS[k].srgb)}"></span>${PATCH_COLOURS[k].name} <span class="muted">${n[k]}</span></li>`,
        )
        .join('')}</ul>`;
      return;
    }
    legend.innerHTML = `<strong>Patches</strong><ul>${PATCH_COLOURS.map(
      (p) => `<li><span class="swatch" style="background:${hex(p.srgb)}"></span>${p.name} <span class="muted">${count[p.kind]}</span></li>`,
    ).join('')}</ul>`;
  }

  /** The heat map's legend: its name, the colour bar and its numbers, and the max / RMS. */
  #heatLegend(view: HeatView): string {
    const range = this.errorRange;
    const fmt = (x: number) => (view === 'normal' ? degrees(x) : percentOfDiagonal(x));
    const srgb = (c: readonly number[]) => `rgb(${c.map((x) => Math.round(255 * x)).join(', ')})`;
    const stats = this.#errorStats().filter((e) => e.totals);
    const totals = stats
      .map((e) => {
        const t = e.totals!;
        const [max, rms] = view === 'normal' ? [t.maxAngle, t.rmsAngle] : [t.maxDistance, t.rmsDistance];
        return `<li>${SURFACE_NAMES[e.surface]}${e.side ? ` (${e.side})` : ''}: max ${fmt(max)} · RMS ${fmt(rms)}</li>`;
      })
      .join('');
    return (
      `<strong>${view === 'normal' ? 'Normal error' : 'Geometry error'}</strong>` +
      `<div class="heat-bar" data-testid="heat-bar" style="background: linear-gradient(to right, ${HEAT_RAMP.map(srgb).join(', ')})"></div>` +
      `<div class="heat-ticks" data-testid="heat-ticks"><span>0</span><span>${fmt(range / 2)}</span><span>≥ ${fmt(range)}</span></div>` +
      `<div class="muted">${view === 'normal' ? 'angle to the exact normal' : 'distance to the exact limit, of the diagonal'}</div>` +
      (totals ? `<ul>${totals}</ul>` : '')
    );
  }

  protected override isAnimating(): boolean {
    return this.params.spin;
  }

  protected override onCameraChanged(): void {
    if (this.geometry?.dependsOnCamera(this.params)) this.#geometryDirty = true;
    this.#otherMode.cameraMoved();
  }

  /** Factors or model changed: rebuild at the next frame. */
  invalidateGeometry(): void {
    this.#geometryDirty = true;
    this.requestFrame();
  }

  /** The camera as drawn at `time`: the user's, turned by the turntable. */
  viewCamera(time: number): OrbitCamera {
    const cam = this.camera!;
    return this.params.spin ? { ...cam, yaw: cam.yaw + time * SPIN_SPEED } : cam;
  }

  protected override onFrame(encoder: GPUCommandEncoder, target: GPUTexture, time: number): void {
    const renderer = this.#renderer;
    const geometry = this.geometry;
    if (!renderer || !geometry) return;
    const cam = this.viewCamera(time);
    const m = cameraMatrices(cam, target.width / Math.max(1, target.height));
    const viewProj = m.viewProj as Float32Array;

    // While spinning, adaptive factors follow the moving camera: rebuild every frame.
    if (this.params.spin && geometry.dependsOnCamera(this.params)) this.#geometryDirty = true;
    this.#rebuiltThisFrame = false;
    // The tessellator works in the cage's own space: hand it the camera in model space.
    const modelViewProj = mat4.multiply(mat4.create(), viewProj, this.#modelMatrix) as Float32Array;
    const worldToModel = mat4.invert(mat4.create(), this.#modelMatrix)!;
    const factors: FactorParams = {
      mode: this.params.mode,
      fixedFactor: this.params.factor,
      lodScale: this.params.lod,
      viewProj: modelViewProj,
      eye: transformPoint(worldToModel, m.eye),
      viewportHeight: target.height,
      fovY: cam.fovY,
    };
    this.#frameFactors = factors;
    const instanced = this.instancedActive ? this.#instanced : null;
    const split = this.splitActive;
    // The compute tessellator builds when it is drawn (alone, or the split view's left half).
    const computeDrawn = !instanced || split;
    if (instanced) {
      // The instanced tessellator draws: its level pass when the levels may have changed.
      if (this.params.spin && this.params.mode === 'adaptive') this.#geometryDirty = true;
      if (this.#geometryDirty) {
        instanced.encode(encoder, this.#instancedLevels(factors));
        if (!computeDrawn) this.#geometryDirty = false;
        this.#rebuilds++;
      } else instanced.copyIfOwed(encoder);
    }
    const dirty = this.#geometryDirty;
    if (computeDrawn && this.#geometryDirty && geometry.output) {
      if (geometry instanceof TessellatorGeometry) geometry.flatBaseline = this.params.flat;
      geometry.encode(encoder, factors);
      this.#builtFactors = factors;
      this.#countsOwed = true;
      this.#geometryDirty = false;
      this.#rebuiltThisFrame = true;
      // The stats count tessellator builds; the flat cage's (drawn meanwhile while a surface is
      // prepared) encodes nothing.
      if (geometry instanceof TessellatorGeometry) this.#rebuilds++;
    }
    // The counts of the latest build, copied once the reader is free: a copy skipped because a
    // read was still in flight would leave the stats' output row at "…" until the next rebuild
    // (and the demo draws on demand: there may be none).
    if (computeDrawn && this.#countsOwed && geometry.output && this.#counts?.idle) {
      this.#counts.copy(encoder, geometry.output.counts);
      this.#countsOwed = false;
    }
    // The comparison's right half, rebuilt with the left one (and when it is new).
    const compare = this.compareActive ? this.#compareGeometry() : null;
    let compareRebuilt = false;
    if (compare?.output && (dirty || this.#compareDirty)) {
      compare.flatBaseline = this.params.flat;
      compare.encode(encoder, factors);
      this.#compareDirty = false;
      compareRebuilt = true;
      this.#rebuilds++;
    }
    // The error passes, after the builds they measure (and the first time, for a new pass).
    const errors = this.#errors;
    const main = computeDrawn && geometry instanceof TessellatorGeometry && isAcc(this.shownSurface) ? geometry : null;
    const measured = [this.errorViewActive || compare ? main : null, compare && isAcc(compare.surface) ? compare : null];
    errors?.retain(measured);
    const tables = this.model && measured.some(Boolean) ? this.#tablesFor(this.model.cage) : null;
    if (errors && this.model && tables && typeof tables !== 'string') {
      measured.forEach((g, i) => {
        if (g && errors.passFor(g, this.model!.cage, tables))
          errors.encode(encoder, g, i ? compareRebuilt : this.#rebuiltThisFrame, factors);
      });
    }
    const heatView = this.params.errorView === 'off' ? null : { view: this.params.errorView, range: this.errorRange };
    const mainHeat = heatView && this.errorViewActive ? (errors?.ready(main) ?? null) : null;
    this.#bindHeat(renderer, mainHeat);

    const view = { viewProj, model: this.#modelMatrix, eye: m.eye };
    const options = {
      wireframe: this.params.wire,
      cage: this.params.cage || this.params.seams,
      patchColours: this.patchColours,
      heat: mainHeat ? heatView : null,
    };
    if (compare && geometry.output) {
      // The same camera twice: the surface on the left half, the compared one on the right, each
      // with its own shadow pass, timing slot and heat values.
      renderer.render(encoder, target, view, { ...options, region: { x0: 0, x1: 0.5, first: true, slot: 0 } });
      const cmpHeat = heatView && isAcc(compare.surface) ? (errors?.ready(compare) ?? null) : null;
      renderer.setMesh(compare.output, this.#closed);
      this.#bindHeat(renderer, cmpHeat);
      renderer.render(encoder, target, view, {
        ...options,
        patchColours: options.patchColours && compare.surface === 'catmull-clark',
        heat: cmpHeat ? heatView : null,
        region: { x0: 0.5, x1: 1, first: false, slot: 1 },
      });
      renderer.setMesh(geometry.output, this.#closed);
      this.#bindHeat(renderer, mainHeat);
    } else if (split && instanced) {
      // The same camera twice: compute's stored mesh on the left half, the instanced
      // tessellator on the right, each with its own shadow pass and timing slot.
      renderer.setDrawer(null);
      renderer.render(encoder, target, view, { ...options, region: { x0: 0, x1: 0.5, first: true, slot: 0 } });
      renderer.setDrawer(instanced.tess);
      renderer.render(encoder, target, view, { ...options, region: { x0: 0.5, x1: 1, first: false, slot: 1 } });
      renderer.setDrawer(null);
    } else renderer.render(encoder, target, view, options);
  }

  /** Hand the renderer the values of `pass` (null: none), unless they are bound already. */
  #bindHeat(renderer: Renderer, pass: { values: GPUBufferBinding } | null): void {
    if (this.#boundHeat === pass) return;
    renderer.setHeat(pass?.values ?? null);
    this.#boundHeat = pass;
  }

  /**
   * The stats' other factor mode (fixed while adaptive is drawn, and the reverse): after this
   * frame, one extra build in that mode whose counts are read back, then the drawn build again
   * (separate submissions: each build writes the tessellator's parameters with writeBuffer).
   * Redone when the model, surface, flat baseline or the other mode's setting change, and, for
   * adaptive, at most once a second while the camera moves. The tessellator times only one
   * build at a time, so these extra builds never take the drawn build's timings.
   */
  #countOtherMode(): void {
    const geometry = this.geometry;
    const reader = this.#otherReader;
    const frame = this.#frameFactors;
    const built = this.#builtFactors;
    if (!(geometry instanceof TessellatorGeometry) || !geometry.output || !reader || !frame || !built || !this.model) return;
    if (this.instancedActive) return;
    const output = geometry.output;
    const other = this.params.mode === 'fixed' ? 'adaptive' : 'fixed';
    const setting = other === 'fixed' ? `factor ${this.params.factor}` : `LOD ${this.params.lod}`;
    const key = [this.controller.version, this.shownSurface, this.params.flat, other, setting].join('|');
    this.#otherMode.update({ key, other, setting }, () => {
      if (!reader.idle) return null;
      const device = this.gpu.device;
      let encoder = device.createCommandEncoder({ label: `count ${other} output` });
      geometry.encode(encoder, { ...frame, mode: other });
      reader.copy(encoder, output.counts);
      device.queue.submit([encoder.finish()]);
      encoder = device.createCommandEncoder({ label: 'rebuild the drawn output' });
      geometry.encode(encoder, built);
      device.queue.submit([encoder.finish()]);
      return reader.read();
    });
  }

  protected override onAfterSubmit(): void {
    const renderer = this.#renderer;
    const geometry = this.geometry;
    this.#countOtherMode();
    // One read of the build's timestamps at a time: while one is mapping, later builds (a
    // turntable rebuilds every frame) go untimed rather than map the same buffer twice.
    const readTess = this.#rebuiltThisFrame && !this.#tessTimingInFlight;
    if (readTess) this.#tessTimingInFlight = true;
    // Each read updates the stats on its own: the counts never wait on a timing read (on some
    // drivers a timestamp buffer's map settles late or not at all).
    const quietly = <T>(p: Promise<T> | undefined, fallback: T) => (p ?? Promise.resolve(fallback)).catch(() => fallback);
    // The counts' map is asked for first, and the timing maps only once it has settled: a
    // timestamp buffer whose map comes back late cannot hold the counts behind it (Debian's
    // Chromium 156 on SwiftShader kept the output row at "…" so). A timing map that never comes
    // back is cancelled after a deadline and timing stops (src/gpu/device/map-within.ts).
    const countsRead = quietly(this.#counts?.read(), null).then((counts) => {
      if (counts) this.#lastCounts = counts;
      this.updateStats();
      if (this.#countsOwed) this.requestFrame();
    });
    if (this.#instanced && this.instancedActive) {
      const view = this.#instanced;
      void quietly(view.read(), null).then((counts) => {
        if (counts) this.#instancedCounts = counts;
        this.updateStats();
        if (view.owed) this.requestFrame();
      });
    }
    if (this.#errors) {
      const errors = this.#errors;
      void quietly(errors.read(), false).then((changed) => {
        if (changed) {
          this.updateStats();
          this.updateLegend();
        }
        if (errors.copyOwed) this.requestFrame();
      });
    }
    void countsRead.then(() =>
      quietly(renderer?.readTimings(), {}).then((draw) => {
        this.#drawTimes = draw;
        this.updateStats();
      }),
    );
    if (readTess) {
      void countsRead.then(() =>
        quietly(geometry?.readTimings(), {}).then((tess) => {
          this.#tessTimingInFlight = false;
          if (Object.keys(tess).length) this.#tessTimes = tess;
          this.updateStats();
        }),
      );
    }
    // Not the interim cage drawn while the model's surface is prepared: ready means the surface asked for.
    if (!this.#firstFrameShown && this.model && !this.controller.preparing) {
      this.#firstFrameShown = true;
      // Ready once the GPU has finished the first complete frame (what screenshots wait for).
      void this.gpu.device.queue.onSubmittedWorkDone().then(() => {
        setLoading(null);
        setPageState('ready');
      });
    }
  }

  /**
   * Redraw the stats panel, at most every 250 ms unless forced. A throttled call leaves a
   * trailing one behind: the demo draws on demand, so no later frame may come to show what
   * arrived in between (counts read back just after the last update would stay "…").
   */
  updateStats(force = false): void {
    this.#statsThrottle.call(force);
  }

  #renderStats(): void {
    const panel = document.getElementById('stats');
    if (!panel || !this.params.ui) return;
    panel.innerHTML = renderStats({
      model: this.model,
      counts: this.#lastCounts,
      vertexCapacity: this.geometry?.output?.vertexCapacity ?? 0,
      triangleCapacity: this.geometry?.output?.triangleCapacity ?? 0,
      source: this.geometry?.kind ?? 'cage',
      surface: {
        shown: this.shownSurface,
        asked: this.params.surface,
        fallback: this.controller.dataError,
        building: this.controller.preparing,
        kinds: this.cc ? kindCounts(this.cc.data.triKind) : undefined,
        tablesMs: this.cc?.ms,
      },
      other: this.#otherMode.counts,
      mode: this.params.mode,
      tessTimes: this.#tessTimes,
      drawTimes: this.#drawTimes,
      timestamps: this.gpu.timestamps,
      timingStalled: !!(this.#renderer?.timingStalled || this.geometry?.timingStalled),
      frameMs: this.timing.frameMs,
      jsMs: this.timing.jsMs,
      rebuilds: this.#rebuilds,
      adapter: this.gpu.adapterName,
      memory: this.memory.counts,
      clamps: this.#clamps,
      errors: this.#errorStats(),
      compare: this.compareActive
        ? {
            surface: this.params.compare!,
            refused:
              this.#compareRefused?.cage === this.model?.cage && this.#compareRefused?.surface === this.params.compare
                ? this.#compareRefused!.message
                : null,
          }
        : null,
      instanced: this.instancedActive
        ? {
            split: this.splitActive,
            surface: this.#instanced?.surface ?? 'phong',
            asked: this.params.instSurface,
            fallback:
              this.#instancedRefused &&
              this.#instancedRefused.cage === this.model?.cage &&
              this.#instancedRefused.surface === this.params.instSurface
                ? this.#instancedRefused.message
                : null,
            counts: this.#instancedCounts,
            setting: this.params.mode === 'fixed' ? `static level ${this.params.level}` : `dynamic LOD ${this.params.lod}`,
          }
        : null,
    });
  }

  /** Load one of the project's models (by name), a URL, or a file; the picker shows which. */
  loadBuiltin(name: string, camera?: CameraParams): Promise<boolean> {
    const dir = modelUrl(name).replace(/[^/]*$/, '');
    const load = async (): Promise<LoadedModel> => {
      // The height map comes with the OBJ, so the first upload already displaces.
      const fetchHeight = async () => {
        const d = await builtinHeight(name, dir);
        return d ? fetchBuiltinHeight(d, dir) : null;
      };
      const [model, height] = await Promise.all([loadModelFromUrl(modelUrl(name), name), fetchHeight().catch((e: Error) => e)]);
      if (height instanceof Error)
        showToast(`${height.message}\n\nShowing ${name} undisplaced.`, { kind: 'info', title: 'No height map', timeout: 8000 });
      else if (height) this.#heights.set(model.cage, height);
      return model;
    };
    return this.controller.loadModel(load, name, { camera, pick: name });
  }

  loadUrl(url: string, camera?: CameraParams): Promise<boolean> {
    const title = url.split('/').pop() || url;
    return this.controller.loadModel(() => loadModelFromUrl(url, title), url, { camera, pick: title });
  }

  loadFile(file: File): Promise<boolean> {
    if (/\.png$/i.test(file.name) || file.type.startsWith('image/')) return this.loadHeightMap(file);
    return this.controller.loadModel(() => loadModelFromFile(file), file.name, { pick: file.name });
  }

  /**
   * A user's PNG height map on the shown model. It needs uvs on every face corner; a file that
   * is not an image (or a model without uvs) leaves the current map as it was and says why.
   */
  async loadHeightMap(file: Blob & { name: string }): Promise<boolean> {
    const model = this.model;
    const fail = (message: string) => {
      showToast(`${message}\n\nThe height map shown before is kept.`, { kind: 'error', title: `Cannot use ${file.name}` });
      return false;
    };
    if (!model) return fail('No model is shown yet.');
    if (uvCoverage(model.cage) !== 'complete')
      return fail(`${model.title} has no texture coordinates on every face corner (OBJ vt and f v/vt): a height map needs them.`);
    let map: HeightEntry['height']['map'];
    try {
      map = await decodeHeightImage(file, file.name);
    } catch (e) {
      return fail((e as Error).message);
    }
    if (this.model !== model) return false; // another model came meanwhile
    const before = this.#heights.get(model.cage);
    const entry: HeightEntry = {
      height: { map, wrap: 'repeat' },
      scale: before?.scale ?? defaultHeightScale(model.cage.positions),
      midLevel: before?.midLevel ?? 0.5,
      source: file.name,
    };
    try {
      for (const tess of this.#allTessellators()) tess.setHeightMap(model.cage, entry.height);
    } catch (e) {
      if (before) for (const tess of this.#allTessellators()) tess.setHeightMap(model.cage, before.height);
      return fail((e as Error).message);
    }
    this.#heights.set(model.cage, entry);
    this.#syncDrawer(model, this.shownSurface); // the instanced tessellator's map
    this.applyDisplacement();
    showToast(`${file.name}: ${map.width}×${map.height}, ${map.bits}-bit, on ${model.title}.`, { title: 'Height map', timeout: 4000 });
    return true;
  }

  /** The tessellators holding the model: the surface drawn and the comparison's. */
  #allTessellators(): TessellatorGeometry[] {
    return [...Object.values(this.#tess), this.#compare].filter((t): t is TessellatorGeometry => !!t);
  }

  /** The displacement settings (panel, URL) on the tessellators drawn (the instanced one too); a redraw. */
  applyDisplacement(model = this.model): void {
    const settings = this.#displacementSettings(model);
    for (const tess of this.#allTessellators()) tess.setDisplacement(settings);
    this.#instanced?.setDisplacement(settings);
    this.invalidateGeometry();
  }

  #displacementSettings(model: LoadedModel | null): { enabled: boolean; scale: number; midLevel: number } {
    const entry = model ? this.#heights.get(model.cage) : undefined;
    return {
      enabled: this.params.disp && entry !== undefined,
      scale: (entry?.scale ?? 0) * this.params.dscale,
      midLevel: entry?.midLevel ?? 0.5,
    };
  }

  /** The cage overlay's lines: plain, or the UV-seam view. */
  uploadCageOverlay(model = this.model): void {
    const renderer = this.#renderer;
    if (!model || !renderer) return;
    let seam: ((a: number, b: number) => boolean) | undefined;
    if (this.params.seams && uvCoverage(model.cage) !== 'none') {
      const seams = uvSeams(model.cage, model.topology).edge;
      seam = (a, b) => seams[findEdge(model.topology, a, b)] === 1;
    }
    this.#cageLines?.vertices.destroy();
    this.#cageLines = uploadCageLines(this.gpu.device, model.cage, seam);
    renderer.setCage(this.#cageLines);
    this.requestFrame();
  }

  /** World bounds, light and camera for the current model and up axis. */
  placeModel(camera?: CameraParams): void {
    if (!this.model) return;
    this.#modelMatrix = upAxisMatrix(this.params.up) as Float32Array;
    this.#bounds = transformBounds(boundsOf(this.model.cage.positions), this.#modelMatrix);
    this.#renderer?.setBounds(this.#bounds);
    this.setCamera(this.#initialCamera(this.#bounds, camera));
    this.invalidateGeometry();
  }

  /** The controller's upload: `model` on this device, drawn as `surface`. Without a device (it
   * was lost) there is nothing to do: onInit uploads what the controller shows to the new one. */
  #upload(model: LoadedModel, surface: Shown, data: CcTables | null): void {
    const renderer = this.#renderer;
    if (!renderer || !this.#flat) return;
    this.#flat.setCage(model.cage);
    const height = this.#heights.get(model.cage)?.height ?? null;
    if (surface !== 'cage') this.#tessellator(surface).setCage(model.cage, surface === 'catmull-clark' ? data?.data : undefined, height);
    this.#closed = isClosed(model.cage, model.topology);
    renderer.setMesh(this.#geometryFor(surface)?.output ?? null, this.#closed);
    // The mesh bound may be another one now: the error views bind their values again.
    this.#boundHeat = null;
    renderer.setHeat(null);
    this.#compareDirty = true;
    const accKinds = surface !== 'cage' ? (this.#tess[surface]?.accPatchKinds ?? null) : null;
    renderer.setPatchKinds(surface === 'catmull-clark' && data ? data.data.triKind : accKinds);
    if (this.#bounds) renderer.setBounds(this.#bounds);
    this.#syncDrawer(model, surface);
    this.uploadCageOverlay(model);
    this.applyDisplacement(model);
  }

  #initialCamera(bounds: Bounds, p?: CameraParams): OrbitCamera {
    const cam = this.frameBounds(bounds);
    const deg = Math.PI / 180;
    return {
      ...cam,
      yaw: p?.yaw != null ? p.yaw * deg : cam.yaw,
      pitch: p?.pitch != null ? p.pitch * deg : cam.pitch,
      distance: p?.dist != null ? p.dist * cam.subject.radius : cam.distance,
    };
  }

  resetCamera(): void {
    if (this.#bounds) this.setCamera(this.frameBounds(this.#bounds));
  }

  /** The current view as URL parameters (camera included), for sharing. */
  shareUrl(): string {
    const cam = this.camera;
    const p: DemoParams = { ...this.params, t: null };
    if (cam) {
      p.yaw = (cam.yaw * 180) / Math.PI;
      p.pitch = (cam.pitch * 180) / Math.PI;
      p.dist = cam.distance / cam.subject.radius;
    }
    return `${location.origin}${location.pathname}${formatParams(p)}`;
  }
}

function kindCounts(kinds: Uint8Array): [number, number, number, number] {
  const n: [number, number, number, number] = [0, 0, 0, 0];
  for (const k of kinds) n[k & 3]++;
  return n;
}

function syncUrl(params: DemoParams): void {
  // Camera angles in the URL describe the first view only: drop them once the user changes anything.
  const p: DemoParams = { ...params, yaw: null, pitch: null, dist: null };
  history.replaceState(null, '', `${location.pathname}${formatParams(p)}`);
}

interface Panel {
  gui: GUI;
  /** Show this model as picked (when it came from the URL, or after a fallback). */
  showPicked(name: string): void;
}

function buildPanel(demo: TessellationDemo, initialModel: string): Panel {
  const p = demo.params;
  const gui = new GUI({ title: 'Controls', width: 272 });
  gui.domElement.classList.add('panel');
  const state = {
    model: initialModel,
    open: () => openFile(demo),
    openHeight: () => openFile(demo, '.png,image/png'),
    reset: () => demo.resetCamera(),
    share: () => {
      const url = demo.shareUrl();
      void navigator.clipboard?.writeText(url).then(
        () => showToast('Link to this view copied.', { timeout: 2500 }),
        () => showToast(url, { title: 'Link to this view' }),
      );
    },
  };
  const options = Object.fromEntries(BUILTIN_MODELS.map((m) => [m.label, m.name]));
  const modelFolder = gui.addFolder('Model');
  const picker = modelFolder
    .add(state, 'model', options)
    .name('cage')
    .onChange((name: string) => {
      p.model = name;
      syncUrl(p);
      void demo.loadBuiltin(name);
    });
  modelFolder
    .add(p, 'up', { 'Z (project models)': 'z', Y: 'y' })
    .name('up axis')
    .onChange(() => {
      syncUrl(p);
      demo.placeModel();
    });
  modelFolder.add(state, 'open').name('open an OBJ file…');

  const tess = gui.addFolder('Tessellation');
  const changed = () => {
    syncUrl(p);
    demo.invalidateGeometry();
  };
  tess
    .add(p, 'surface', Object.fromEntries(Object.entries(SURFACE_NAMES).map(([k, v]) => [v, k])))
    .name('surface')
    .onChange(() => {
      syncUrl(p);
      showFlat();
      showErrors();
      void demo.controller.setSurface(p.surface);
    });
  const flat = tess.add(p, 'flat').name('flat baseline').onChange(changed);
  const showFlat = () => flat.show(p.surface === 'catmull-clark');
  showFlat();
  tess
    .add(p, 'mode', { adaptive: 'adaptive', fixed: 'fixed' })
    .name('factors')
    .onChange(() => {
      showMode();
      changed();
    });
  const lod = tess.add(p, 'lod', LOD_RANGE.min, LOD_RANGE.max, 0.05).name('LOD scale').onChange(changed);
  const factor = tess.add(p, 'factor', FACTOR_RANGE.min, FACTOR_RANGE.max, 0.25).name('fixed factor').onChange(changed);
  const showMode = () => {
    const instancedOnly = p.tessellator === 'instanced' && !p.split;
    lod.show(p.mode === 'adaptive');
    factor.show(p.mode === 'fixed' && !instancedOnly);
  };
  showMode();

  const view = gui.addFolder('View');
  const redraw = () => {
    syncUrl(p);
    demo.requestFrame();
  };
  view
    .add(p, 'patches')
    .name('patch colours')
    .onChange(() => {
      demo.updateLegend();
      redraw();
    });
  // The ACC error views (the NVIDIA sample's names), for the ACC surfaces.
  const errState = { range: demo.errorRange };
  const errView = view
    .add(p, 'errorView', { off: 'off', 'geometry error': 'geometry', 'normal error': 'normal' })
    .name('error view')
    .onChange((v: DemoParams['errorView']) => {
      // A range typed for one unit means nothing in the other: back to the view's default.
      p.errRange = null;
      errState.range = demo.errorRange;
      errRange.updateDisplay();
      showErrors();
      syncUrl(p);
      demo.setErrorView(v, null);
    });
  const errRange = view
    .add(errState, 'range')
    .name('error range')
    .onFinishChange((v: number) => {
      const range = Number.isFinite(v) && v > 0 ? Math.min(ERR_RANGE.max, Math.max(ERR_RANGE.min, v)) : null;
      errState.range = range ?? demo.errorRange;
      errRange.updateDisplay();
      syncUrl({ ...p, errRange: range });
      demo.setErrorView(p.errorView, range);
    });
  errRange.domElement.title = 'The error drawn red: a fraction of the diagonal (geometry) or degrees (normal).';
  // Shown where they apply (an ACC surface, or a comparison already asked for): the other
  // surfaces' panel stays as it was.
  const showErrors = () => {
    const acc = isAcc(p.surface) || isAcc(p.compare);
    errView.show(acc);
    errRange.show(acc && p.errorView !== 'off');
    compare.show(acc || p.compare !== null);
  };
  const compareState = { compare: p.compare ?? 'off' };
  const compare = view
    .add(compareState, 'compare', { off: 'off', ...Object.fromEntries(COMPARE_SURFACES.map((c) => [SURFACE_NAMES[c], c])) })
    .name('compare (right half)')
    .onChange((v: string) => {
      const c = v === 'off' ? null : (v as CompareSurface);
      p.compare = c;
      syncUrl(p);
      showErrors();
      demo.setCompare(c);
    });
  showErrors();
  view.add(p, 'wire').name('wireframe').onChange(redraw);
  view.add(p, 'cage').name('cage overlay').onChange(redraw);
  view.add(p, 'spin').name('turntable').onChange(redraw);
  // Displacement by the model's height map (the project's displaced models have one; drop or
  // open a PNG for a model with uvs).
  const disp = gui.addFolder('Displacement');
  const displaced = () => {
    syncUrl(p);
    demo.applyDisplacement();
  };
  disp.add(p, 'disp').name('displace').onChange(displaced);
  disp.add(p, 'dscale', DSCALE_RANGE.min, DSCALE_RANGE.max, 0.05).name('scale (× the map’s)').onChange(displaced);
  disp
    .add(p, 'seams')
    .name('UV seams')
    .onChange(() => {
      syncUrl(p);
      demo.uploadCageOverlay();
    });
  disp.add(state, 'openHeight').name('open a PNG height map…');
  if (p.disp && p.dscale === 1 && !p.seams) disp.close();
  view.add(state, 'reset').name('reset camera');
  view.add(state, 'share').name('copy link to this view');
  // NVIDIA's instanced power-of-two tessellator beside the compute one (closed unless in use).
  const inst = gui.addFolder('Instanced tessellator');
  inst
    .add(p, 'tessellator', { 'compute (built once)': 'compute', 'instanced (per pass)': 'instanced' })
    .name('tessellator')
    .onChange((kind: DemoParams['tessellator']) => {
      syncUrl(p);
      showMode();
      demo.setTessellator(kind);
    });
  inst
    .add(p, 'split')
    .name('split: compute | inst.')
    .onChange((split: boolean) => {
      syncUrl(p);
      showMode();
      demo.setSplit(split);
    });
  inst
    .add(p, 'instSurface', {
      Phong: 'phong',
      'Catmull-Clark': 'catmull-clark',
      'Bezier ACC': 'bezier-acc',
      'Gregory ACC': 'gregory-acc',
      'Pm ACC': 'pm-acc',
    })
    .name('its surface')
    .onChange((v: DemoParams['instSurface']) => {
      syncUrl(p);
      demo.setInstancedSurface(v);
    });
  inst
    .add(p, 'flatShade')
    .name('flat shading')
    .onChange((v: boolean) => {
      syncUrl(p);
      demo.setInstancedFlat(v);
    });
  // Its static LOD (factors: fixed): one power-of-two level for every patch; adaptive factors
  // give it its dynamic LOD, scaled by the LOD scale.
  inst
    .add(p, 'level', [...LEVEL_CHOICES])
    .name('level (fixed)')
    .onChange((v: number | string) => {
      p.level = Number(v);
      changed();
    });
  if (p.tessellator !== 'instanced' && !p.split) inst.close();
  if (window.matchMedia('(max-width: 640px)').matches) gui.close();
  return {
    gui,
    showPicked(name: string) {
      state.model = name;
      picker.updateDisplay();
    },
  };
}

function openFile(demo: TessellationDemo, accept = '.obj,text/plain'): void {
  const input = document.createElement('input');
  input.type = 'file';
  input.accept = accept;
  input.addEventListener('change', () => {
    const file = input.files?.[0];
    if (file) void demo.loadFile(file);
  });
  input.click();
}

function enableDrop(demo: TessellationDemo): void {
  const overlay = document.getElementById('drop-target')!;
  let depth = 0;
  const hasFiles = (e: DragEvent) => [...(e.dataTransfer?.types ?? [])].includes('Files');
  window.addEventListener('dragenter', (e) => {
    if (!hasFiles(e)) return;
    depth++;
    overlay.hidden = false;
  });
  window.addEventListener('dragleave', () => {
    depth = Math.max(0, depth - 1);
    if (depth === 0) overlay.hidden = true;
  });
  window.addEventListener('dragover', (e) => {
    if (hasFiles(e)) e.preventDefault();
  });
  window.addEventListener('drop', (e) => {
    e.preventDefault();
    depth = 0;
    overlay.hidden = true;
    const file = e.dataTransfer?.files?.[0];
    if (file) void demo.loadFile(file);
  });
}

async function main(): Promise<void> {
  const params = parseParams(location.search);
  document.body.classList.toggle('no-ui', !params.ui);
  const canvas = document.getElementById('view') as HTMLCanvasElement;
  const demo = new TessellationDemo(canvas, params);
  // Debug and test hook: the live demo, and a way to simulate a device loss.
  (window as unknown as { tessellab: unknown }).tessellab = {
    demo,
    loseDevice: () => demo.gpu.device.destroy(),
    /** Hold back (true) or hand over (false) models' surface data: the page shows what it draws meanwhile. */
    holdPreparation: (hold: boolean) => demo.holdPreparation(hold),
    /** The bytes (and counts) of the page's live GPU buffers and textures, and per label. */
    gpuMemory: () => ({ ...demo.memory.counts, byLabel: demo.memory.byLabel() }),
    /** The instanced tessellator's bucket draw records (GPU) and the CPU's count (static mode). */
    instancedRecords: () => demo.instancedRecords(),
  };
  // Test hook: hold the first model's surface data from the start (e2e/demo.spec.ts).
  if ((window as { tessellabHoldPreparation?: boolean }).tessellabHoldPreparation) demo.holdPreparation(true);
  if (!(await demo.start())) return;

  const name = params.model ?? DEFAULT_MODEL;
  demo.panel = params.ui ? buildPanel(demo, isModelUrl(name) ? DEFAULT_MODEL : name) : null;
  enableDrop(demo);

  const camera = { yaw: params.yaw, pitch: params.pitch, dist: params.dist };
  if (isModelUrl(name)) {
    await demo.loadUrl(name, camera);
  } else if (!(await demo.loadBuiltin(name, camera)) && name !== DEFAULT_MODEL && !demo.model) {
    await demo.loadBuiltin(DEFAULT_MODEL, camera);
  }
}

void main();
