/**
 * What the demo draws, on the current device: the model (the controller's: src/app/controller.ts)
 * placed in the world, its surface's tessellator and the flat cage, the comparison's right half,
 * the instanced tessellator, the error views, height maps and the cage overlay; the mode that
 * draws them (src/app/modes/; which one: pick-mode.ts); and the load flow that changes them
 * (models by name, URL or file, and PNG height maps). Drawing its frames, the stats and the
 * legend are the demo's (src/app/tessellation-demo.ts).
 */
import { isClosed, LimitError, type Cage } from '../mesh/index.ts';
import { MAX_FACTOR } from '../pattern/max-factor.ts';
import { boundsOf, transformBounds, upAxisMatrix, type Bounds, type OrbitCamera } from '../gpu/render/camera.ts';
import { uploadCageLines, type CageLines } from '../gpu/render/cage-mesh.ts';
import { Renderer } from '../gpu/render/renderer.ts';
import { clampMessages, wantedOutputLimits } from './limits.ts';
import { cageTooLarge } from '../gpu/tess/arenas.ts';
import type { LimitName } from '../gpu/device/device.ts';
import { ArrivedTables, CcTableCache, type CcTables } from './cc-tables.ts';
import { BUILDING, DemoController, type DemoPorts, type Shown } from './controller.ts';
import { TessPipelineCache } from './tess-pipelines.ts';
import { DemoBase } from './demo-base.ts';
import { CageGeometry, TessellatorGeometry, type GeometrySource, type TessSurface } from './geometry.ts';
import { loadModelFromFile, loadModelFromUrl, type LoadedModel } from './models.ts';
import { DEFAULT_PARAMS, formatParams, type DemoParams } from './params.ts';
import { HEAT_DEFAULT_RANGE } from '../gpu/acc/heat.ts';
import { ErrorViews } from './error-views.ts';
import { setLoading, setPageState, showToast } from './ui.ts';
import type { DisplacementSettings, HeightEntry } from './displacement.ts';
import { findEdge, uvCoverage, uvSeams } from '../mesh/index.ts';
import { preparedAhead, SURFACE_NAMES } from './surfaces.ts';
import { CompareView } from './compare-view.ts';
import { InstancedDrawer } from './instanced-drawer.ts';
import { fetchBuiltinModel, readHeightMap, userHeightEntry } from './model-loading.ts';
import { makeMode } from './modes/make-mode.ts';
import type { DemoMode, ModeHost } from './modes/mode.ts';
import { ModeSwitch } from './modes/mode-switch.ts';
import { pickMode } from './modes/pick-mode.ts';

/** How a model is first placed: the URL's camera and up axis (for the model the URL names). A
 * model picked or opened later has none: it opens Y-up (OBJ's convention), framed afresh. */
export type CameraParams = Partial<Pick<DemoParams, 'yaw' | 'pitch' | 'dist' | 'up'>>;

/** What a model request carries to the page: the first view, and what the cage picker shows. */
interface Placement {
  camera?: CameraParams;
  pick: string;
}

/** Where the page shows which model is picked (the panel, src/app/panel.ts). */
export interface PickerDisplay {
  /** Show this model as picked (when it came from the URL, or after a fallback). */
  showPicked(name: string): void;
}

export abstract class DemoScene extends DemoBase {
  params: DemoParams;
  /** The model, its surface data and the surface drawn, and the one flow that changes them. */
  readonly controller: DemoController<LoadedModel, CcTables, Placement>;
  panel: PickerDisplay | null = null;
  /** The model's bounds in world space, and its model-to-world rotation (up axis to +Y). */
  #bounds: Bounds | null = null;
  protected modelMatrix = upAxisMatrix(DEFAULT_PARAMS.up) as Float32Array;

  protected renderer: Renderer | null = null;
  /** The tessellator of the surface drawn (one at a time: each holds big output buffers), and
   * the flat cage (for before/after). */
  protected tess: Partial<Record<TessSurface, TessellatorGeometry>> = {};
  /** Height maps by cage: the project's displaced models' (fetched with the OBJ) and PNGs the
   * user dropped (src/app/displacement.ts). */
  #heights = new WeakMap<LoadedModel['cage'], HeightEntry>();
  #flat: CageGeometry | null = null;
  #cageLines: CageLines | null = null;
  /** What #cageLines were built for (null: nothing, the overlay is off). */
  #cageLinesKey: { cage: Cage; seams: boolean } | null = null;
  /** The instanced tessellator (`tessellator=instanced`, or the split view's right half). */
  protected readonly instanced = new InstancedDrawer();

  /** Catmull-Clark data per cage (topology only, cached): the controller's surface data. */
  readonly #ccTables = new CcTableCache();
  /** The same data once it has arrived, for the error views and a Catmull-Clark comparison: the
   * error passes start with the next frame; a Catmull-Clark comparison builds then. */
  protected readonly tables = new ArrivedTables(this.#ccTables, () => {
    this.compare.dirty = true;
    this.requestFrame();
    this.updateStats(true);
  });

  /** The ACC error views' passes (src/app/error-views.ts), made with the device. */
  protected errors: ErrorViews | null = null;
  /** The error view's values the renderer has bound (their pass), to bind again only on change. */
  #boundHeat: object | null = null;
  /** The comparison view's right half (`compare=`). */
  protected readonly compare = new CompareView();
  /** Whether the model's cage is closed (the renderer culls back faces). */
  protected closed = false;

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

  /** The mode drawn (src/app/modes/), swapped when pickMode's answer changes. */
  readonly #modes: ModeSwitch<DemoMode>;

  constructor(canvas: HTMLCanvasElement, params: DemoParams) {
    super(canvas, { frozenTime: params.t });
    this.params = params;
    this.controller = new DemoController(this.#ports(), params.surface);
    const host = this.#modeHost();
    this.#modes = new ModeSwitch((id) => makeMode(id, host));
  }

  /** The mode that draws what is asked for, as far as the shown model and the device allow. */
  get mode(): DemoMode {
    const caps = { model: this.model !== null, shown: this.shownSurface, vertexStorage: this.renderer?.vertexStorage ?? true };
    return this.#modes.to(pickMode(this.params, caps));
  }

  /** What the modes draw with: the scene's objects as they are at each call. */
  #modeHost(): ModeHost {
    const scene = this;
    return {
      get params() {
        return scene.params;
      },
      get shown() {
        return scene.shownSurface;
      },
      get model() {
        return scene.model;
      },
      get tessellator() {
        const geometry = scene.geometry;
        return geometry instanceof TessellatorGeometry ? geometry : null;
      },
      get cc() {
        return scene.cc;
      },
      tables: this.tables,
      instanced: this.instanced,
      compare: this.compare,
      get errors() {
        return scene.errors;
      },
      get errorRange() {
        return scene.errorRange;
      },
      get closed() {
        return scene.closed;
      },
      compareGeometry: () => this.compareGeometry(),
    };
  }

  /** The file whose parse is in flight (its progress is said only while it is the latest). */
  #loadingFile: File | null = null;

  /** The exact surface's pipelines on this device (made at init), compiled when first asked for. */
  #pipelines: TessPipelineCache | null = null;
  /** The controller waits for a surface (loading's `surface`), and for which cage's data. */
  #waitingForSurface = false;
  #preparing: Cage | null = null;

  /** What the surface's wait is for, said while the controller waits: the data, else the shaders. */
  #sayWait(): void {
    if (!this.#waitingForSurface) return;
    const cage = this.#preparing;
    if (cage && !this.#ccTables.has(cage)) setLoading(BUILDING);
    else if (this.#pipelines?.compiling('catmull-clark')) setLoading("Compiling the exact surface's shaders…");
    else setLoading(BUILDING);
  }

  /** The page's side of the controller. */
  #ports(): DemoPorts<LoadedModel, CcTables, Placement> {
    return {
      // The surface data and the exact surface's pipelines, both before its first frame (the flat
      // cage is drawn meanwhile); once compiled, the pipelines are kept for every later model.
      prepareSurface: (model) =>
        this.#hold.promise.then(() => {
          this.#preparing = model.cage;
          // The tables first (a refused cage compiles nothing), then the pipelines, said as awaited.
          return this.#ccTables.get(model.cage).then((t) => {
            const pipelines = this.#pipelines?.prepare('catmull-clark');
            this.#sayWait();
            return pipelines ? pipelines.then(() => t) : t;
          });
        }),
      surfaceReady: (model) => !this.#hold.held && this.#ccTables.has(model.cage) && !!this.#pipelines?.get('catmull-clark'),
      upload: (model, surface, data) => this.#upload(model, surface, data),
      loading: (message, surface = false) => {
        this.#waitingForSurface = surface;
        if (this.#waitingForSurface) this.#sayWait();
        else setLoading(message);
      },
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
          // The up axis belongs to the model it was chosen for: a new model opens Y-up unless its
          // link says otherwise.
          this.params.up = placement?.camera?.up ?? DEFAULT_PARAMS.up;
          this.placeModel(placement?.camera);
        }
        if (placement) this.panel?.showPicked(placement.pick);
        this.onModelShown(previous);
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
  protected clamps: string[] = [];

  #reportClamps(): void {
    const clamps = clampMessages(this.gpu.clamps, this.gpu.device.limits, this.#requestedCapacity);
    const before = this.clamps.join('\n');
    this.clamps = clamps;
    // Once per device, and again only if a new device clamps differently.
    if (clamps.length && clamps.join('\n') !== before) {
      showToast(clamps.join('\n'), { kind: 'info', title: "Clamped to this GPU's limits", timeout: 10_000 });
    }
  }

  protected override async onInit(): Promise<void> {
    const device = this.gpu.device;
    this.#reportClamps();
    this.renderer = Renderer.create(device, { colorFormat: this.renderFormat, timestamps: this.gpu.timestamps });
    this.#pipelines = new TessPipelineCache(device);
    this.#flat = new CageGeometry(device);
    this.errors = new ErrorViews(device);
    this.#boundHeat = null;
    // After a device loss: upload the current model to the new device.
    this.controller.reupload();
  }

  protected override onDeviceLost(): void {
    this.renderer = null;
    this.#pipelines = null;
    this.tess = {};
    this.#flat = null;
    this.#cageLines = null;
    this.#cageLinesKey = null;
    this.instanced.deviceLost();
    this.errors = null;
    this.#boundHeat = null;
    this.compare.deviceLost();
  }

  /** The colour bar's top, in the view's unit. */
  get errorRange(): number {
    const view = this.params.errorView === 'normal' ? 'normal' : 'geometry';
    return this.params.errRange ?? HEAT_DEFAULT_RANGE[view];
  }

  /** The comparison's tessellator with the model's cage on it, made or re-uploaded as needed;
   * null while its data is not there, or when it refused the cage. */
  protected compareGeometry(): TessellatorGeometry | null {
    const model = this.model,
      want = this.params.compare;
    if (!model || !want) return null;
    const cage = model.cage;
    const displacement = this.#displacementSettings(model);
    return this.compare.prepare(
      this.gpu.device,
      this.params.capacity * 1e6,
      model,
      want,
      () => this.tables.get(cage),
      this.#heights.get(cage),
      displacement,
    );
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
    return surface === 'cage' ? this.#flat : (this.tess[surface] ?? null);
  }

  /** Hand the renderer the instanced tessellator (the model's patches uploaded) or take it back,
   * for `model` drawn as `surface` (at upload: before the controller commits them). */
  protected syncDrawer(model: LoadedModel | null, surface: Shown): void {
    const renderer = this.renderer;
    if (!renderer) return;
    renderer.setDrawer(null);
    if (!model) return;
    // The mode `model` and `surface` will be drawn in (src/app/modes/pick-mode.ts): not on the flat
    // cage, nor on a device without vertex-stage storage (compatibility mode; the clamp message
    // says so once), where the compute tessellator draws.
    const mode = pickMode(this.params, { model: true, shown: surface, vertexStorage: renderer.vertexStorage });
    if (mode !== 'instanced' && mode !== 'split') return;
    const height = this.#heights.get(model.cage)?.height ?? null;
    const settings = this.#displacementSettings(model);
    const view = this.instanced.sync(
      this.gpu.device,
      renderer.shadingResources,
      model,
      this.params.instSurface,
      height,
      settings,
      this.params.flatShade,
    );
    // The split view hands it over per half, in its frame (src/app/modes/split-mode.ts).
    if (mode === 'instanced') renderer.setDrawer(view.tess);
  }

  /** Test hook: the GPU's bucket draw records of the latest level pass, and the CPU's count for
   * static mode (null in dynamic mode). */
  instancedRecords(): ReturnType<InstancedDrawer['records']> {
    return this.mode.instanced ? this.instanced.records() : Promise.resolve(null);
  }

  /** The tessellator for `surface`, created on first use (the other one is freed). */
  #tessellator(surface: TessSurface): TessellatorGeometry {
    let tess = this.tess[surface];
    if (!tess) {
      for (const other of Object.values(this.tess)) other.destroy();
      tess = new TessellatorGeometry(this.gpu.device, this.params.capacity * 1e6, surface, this.#pipelines?.get(surface));
      this.tess = { [surface]: tess };
    }
    return tess;
  }

  /** Hand the renderer the values of `pass` (null: none), unless they are bound already. */
  protected bindHeat(renderer: Renderer, pass: { values: GPUBufferBinding } | null): void {
    if (this.#boundHeat === pass) return;
    renderer.setHeat(pass?.values ?? null);
    this.#boundHeat = pass;
  }

  /** The project's models once fetched: picking one again shows the same cage, whose surface
   * data (cached per cage) is then not prepared again, as the panel's "cached" says. A failed
   * fetch is not kept. */
  readonly #builtins = new Map<string, Promise<LoadedModel>>();

  /** Load one of the project's models (by name), a URL, or a file; the picker shows which. */
  loadBuiltin(name: string, camera?: CameraParams): Promise<boolean> {
    const load = () => {
      let model = this.#builtins.get(name);
      if (!model) {
        model = fetchBuiltinModel(name, this.#heights);
        this.#builtins.set(name, model);
        model.catch(() => this.#builtins.delete(name));
      }
      return model;
    };
    return this.controller.loadModel(load, name, { camera, pick: name });
  }

  loadUrl(url: string, camera?: CameraParams): Promise<boolean> {
    const title = url.split('/').pop() || url;
    return this.controller.loadModel(() => loadModelFromUrl(url, title).then((m) => this.#fits(m)), url, { camera, pick: title });
  }

  /** `model`, or a LimitError in plain words when this device cannot hold its cage: said from
   * its counts, before the preparation (prepareMesh, the Catmull-Clark tables) that would take
   * the page's main thread for most of a minute on a cage of a million faces and then fail. */
  #fits(model: LoadedModel): LoadedModel {
    const tooLarge = cageTooLarge(model.cage, MAX_FACTOR, this.gpu.device.limits.maxStorageBufferBindingSize);
    if (tooLarge) throw new LimitError(tooLarge);
    return model;
  }

  async loadFile(file: File): Promise<boolean> {
    if (/\.png$/i.test(file.name) || file.type.startsWith('image/')) return this.loadHeightMap(file);
    // Read and parsed in a worker: the page stays responsive, and says what it is doing.
    const progress = (line: string) => {
      if (this.#loadingFile === file) setLoading(`Loading ${file.name}: ${line}…`);
    };
    this.#loadingFile = file;
    // The worker refuses a cage this device cannot hold from its counts, before handing it over.
    const fits = { maxFactor: MAX_FACTOR, bindingLimit: this.gpu.device.limits.maxStorageBufferBindingSize };
    const load = () => loadModelFromFile(file, progress, fits).then((m) => this.#fits(m));
    const shown = await this.controller.loadModel(load, file.name, { pick: file.name }).finally(() => {
      if (this.#loadingFile === file) this.#loadingFile = null;
    });
    // The URL no longer names the model shown before: a local file has no name a link can load.
    if (shown && this.model?.localFile) {
      this.params.model = null;
      this.syncUrl();
    }
    return shown;
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
    let map: HeightEntry['height']['map'];
    try {
      map = await readHeightMap(file, model);
    } catch (e) {
      return fail((e as Error).message);
    }
    if (this.model !== model) return false; // another model came meanwhile
    const before = this.#heights.get(model.cage);
    const entry = userHeightEntry(map, file.name, model, before);
    try {
      for (const tess of this.#allTessellators()) tess.setHeightMap(model.cage, entry.height);
    } catch (e) {
      if (before) for (const tess of this.#allTessellators()) tess.setHeightMap(model.cage, before.height);
      return fail((e as Error).message);
    }
    this.#heights.set(model.cage, entry);
    this.syncDrawer(model, this.shownSurface); // the instanced tessellator's map
    this.applyDisplacement();
    showToast(`${file.name}: ${map.width}×${map.height}, ${map.bits}-bit, on ${model.title}.`, { title: 'Height map', timeout: 4000 });
    return true;
  }

  /** The tessellators holding the model: the surface drawn and the comparison's. */
  #allTessellators(): TessellatorGeometry[] {
    return [...Object.values(this.tess), this.compare.tessellator].filter((t): t is TessellatorGeometry => !!t);
  }

  /** The displacement settings (panel, URL) on the tessellators drawn (the instanced one too); a redraw. */
  applyDisplacement(model = this.model): void {
    const settings = this.#displacementSettings(model);
    for (const tess of this.#allTessellators()) tess.setDisplacement(settings);
    this.instanced.view?.setDisplacement(settings);
    this.invalidateGeometry();
  }

  #displacementSettings(model: LoadedModel | null): DisplacementSettings {
    const entry = model ? this.#heights.get(model.cage) : undefined;
    return {
      enabled: this.params.disp && entry !== undefined,
      scale: (entry?.scale ?? 0) * this.params.dscale,
      midLevel: entry?.midLevel ?? 0.5,
    };
  }

  /** The cage overlay's lines: plain, or the UV-seam view. */
  /** The cage overlay's lines (and the UV seams among them), built while the overlay is shown:
   * 80-100 ms of the page's thread on a 40,000-face cage, for lines nobody had asked to see. */
  uploadCageOverlay(model = this.model): void {
    const renderer = this.renderer;
    if (!model || !renderer) return;
    const key = this.params.cage || this.params.seams ? { cage: model.cage, seams: this.params.seams } : null;
    const built = this.#cageLinesKey;
    if (key?.cage === built?.cage && key?.seams === built?.seams) return;
    this.#cageLines?.vertices.destroy();
    this.#cageLines = null;
    this.#cageLinesKey = key;
    renderer.setCage(null);
    this.requestFrame();
    if (!key) return;
    let seam: ((a: number, b: number) => boolean) | undefined;
    if (this.params.seams && uvCoverage(model.cage) !== 'none') {
      const seams = uvSeams(model.cage, model.topology).edge;
      seam = (a, b) => seams[findEdge(model.topology, a, b)] === 1;
    }
    this.#cageLines = uploadCageLines(this.gpu.device, model.cage, seam);
    renderer.setCage(this.#cageLines);
    this.requestFrame();
  }

  /** Where the model's own +Y points in the world (the camera's up is the world's +Y): [0, 1, 0] for a
   * model read Y-up, [0, 0, -1] for one read Z-up. A test hook (e2e/talk-models.spec.ts). */
  modelUp(): number[] {
    return [this.modelMatrix[4], this.modelMatrix[5], this.modelMatrix[6]].map((c) => Math.round(c * 1e6) / 1e6 + 0);
  }

  /** World bounds, light and camera for the current model and up axis. */
  placeModel(camera?: CameraParams): void {
    if (!this.model) return;
    this.modelMatrix = upAxisMatrix(this.params.up) as Float32Array;
    this.#bounds = transformBounds(boundsOf(this.model.cage.positions), this.modelMatrix);
    this.renderer?.setBounds(this.#bounds);
    this.setCamera(this.#initialCamera(this.#bounds, camera));
    this.invalidateGeometry();
  }

  /** The controller's upload: `model` on this device, drawn as `surface`. Without a device (it
   * was lost) there is nothing to do: onInit uploads what the controller shows to the new one. */
  #upload(model: LoadedModel, surface: Shown, data: CcTables | null): void {
    const renderer = this.renderer;
    if (!renderer || !this.#flat) return;
    this.#flat.setCage(model.cage, model.flat);
    if (surface !== 'cage') this.#flat.release();
    const height = this.#heights.get(model.cage)?.height ?? null;
    if (surface !== 'cage') {
      const ahead = preparedAhead(surface) ? data : null;
      this.#tessellator(surface).setCage(model.cage, ahead?.data, height, ahead?.mesh);
    }
    this.closed = isClosed(model.cage, model.topology);
    renderer.setMesh(this.#geometryFor(surface)?.output ?? null, this.closed);
    // The mesh bound may be another one now: the error views bind their values again.
    this.#boundHeat = null;
    renderer.setHeat(null);
    this.compare.dirty = true;
    const accKinds = surface !== 'cage' ? (this.tess[surface]?.accPatchKinds ?? null) : null;
    renderer.setPatchKinds(preparedAhead(surface) && data ? data.data.triKind : accKinds);
    if (this.#bounds) renderer.setBounds(this.#bounds);
    this.syncDrawer(model, surface);
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

  /** The address bar follows the parameters (camera angles describe the first view only: they
   * go once the visitor changes anything). */
  syncUrl(): void {
    const p: DemoParams = { ...this.params, yaw: null, pitch: null, dist: null };
    history.replaceState(null, '', `${location.pathname}${formatParams(p)}`);
  }

  /** The current view as URL parameters (camera included), for sharing; null while a local file
   * is shown (a link cannot carry it). */
  shareUrl(): string | null {
    if (this.model?.localFile) return null;
    const cam = this.camera;
    const p: DemoParams = { ...this.params, t: null };
    if (cam) {
      p.yaw = (cam.yaw * 180) / Math.PI;
      p.pitch = (cam.pitch * 180) / Math.PI;
      p.dist = cam.distance / cam.subject.radius;
    }
    return `${location.origin}${location.pathname}${formatParams(p)}`;
  }

  /** A model (or another surface of it) is shown now: what was counted for the last one goes,
   * and its first frame is drawn. */
  protected abstract onModelShown(previous: LoadedModel | null): void;
  /** Redraw the stats panel (throttled unless forced). */
  abstract updateStats(force?: boolean): void;
  /** Redraw the legend (patch colours or the error views' colour bar). */
  abstract updateLegend(): void;
  /** Something the build depends on changed: rebuild at the next frame. */
  abstract invalidateGeometry(): void;
}
