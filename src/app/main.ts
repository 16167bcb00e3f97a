/**
 * The demo page: a cage, tessellated on the GPU (the Catmull-Clark limit surface, or Phong
 * tessellation), drawn lit and shadowed with optional wireframe, cage overlay and patch colours.
 * The geometry is rebuilt only when the model, the factors or (in adaptive mode) the camera
 * change; every other frame draws the stored buffers again. The Catmull-Clark tables are built
 * on the CPU once per model, in a worker (cc-tables.ts).
 */
import GUI from 'lil-gui';
import { CageError, isClosed } from '../mesh/index.ts';
import { mat4 } from 'gl-matrix';
import { boundsOf, cameraMatrices, transformBounds, transformPoint, upAxisMatrix, type Bounds, type OrbitCamera } from '../gpu/camera.ts';
import { uploadCageLines, type CageLines } from '../gpu/cage-mesh.ts';
import { PATCH_COLOURS, Renderer } from '../gpu/renderer.ts';
import type { FactorParams } from '../gpu/types.ts';
import { CcTableCache, type CcTables } from './cc-tables.ts';
import { DemoBase } from './demo-base.ts';
import { CountsReader, type MeshCounts } from './counts.ts';
import { CageGeometry, TessellatorGeometry, type GeometrySource, type TessSurface } from './geometry.ts';
import {
  BUILTIN_MODELS, DEFAULT_MODEL, fetchModelList, loadModelFromFile, loadModelFromUrl, modelUrl,
  type LoadedModel, type ModelEntry,
} from './models.ts';
import { FACTOR_RANGE, formatParams, isModelUrl, LOD_RANGE, parseParams, type DemoParams, type Surface } from './params.ts';
import { renderStats, type OtherModeCounts } from './stats.ts';
import { setLoading, setPageState, showToast } from './ui.ts';

/** Turntable speed, radians per second. */
const SPIN_SPEED = 0.35;

class TessellationDemo extends DemoBase {
  params: DemoParams;
  models: ModelEntry[] = BUILTIN_MODELS;
  model: LoadedModel | null = null;
  /** The model's bounds in world space, and its model-to-world rotation (up axis to +Y). */
  bounds: Bounds | null = null;
  modelMatrix = upAxisMatrix('z') as Float32Array;

  renderer: Renderer | null = null;
  /** The tessellator of the surface drawn (one at a time: each holds big output buffers), and
   * the flat cage (for before/after). */
  #tess: Partial<Record<TessSurface, TessellatorGeometry>> = {};
  flat: CageGeometry | null = null;
  cageLines: CageLines | null = null;
  counts: CountsReader | null = null;

  /** Catmull-Clark tables per cage (built in a worker), the current model's, or why it has none. */
  readonly ccTables = new CcTableCache();
  cc: CcTables | null = null;
  ccError: string | null = null;
  buildingTables = false;
  #loadSerial = 0;

  /** The other factor mode's counts (an extra build, then the drawn one again), and when to redo it. */
  otherCounts: OtherModeCounts | null = null;
  #otherReader: CountsReader | null = null;
  #probeKey = '';
  #probeCameraMoved = false;
  #lastProbeAt = 0;
  #probeTimer = 0;
  /** The factors of this frame's camera, and of the build the output holds now. */
  #frameFactors: FactorParams | null = null;
  #builtFactors: FactorParams | null = null;

  lastCounts: MeshCounts | null = null;
  /** GPU milliseconds of the last rebuild's passes, and of the last frame's draw passes. */
  tessTimes: Record<string, number> = {};
  drawTimes: Record<string, number> = {};
  rebuilds = 0;
  #geometryDirty = true;
  #rebuiltThisFrame = false;
  #tessTimingInFlight = false;
  #statsDue = 0;
  #statsTimer = 0;
  #firstFrameShown = false;

  constructor(canvas: HTMLCanvasElement, params: DemoParams) {
    super(canvas, { frozenTime: params.t });
    this.params = params;
  }

  protected override async onInit(): Promise<void> {
    const device = this.gpu.device;
    this.renderer = Renderer.create(device, { colorFormat: this.renderFormat, timestamps: this.gpu.timestamps });
    this.flat = new CageGeometry(device);
    this.counts = new CountsReader(device);
    this.#otherReader = new CountsReader(device);
    this.#probeKey = '';
    // After a device loss: upload the current model to the new device.
    if (this.model) this.#uploadModel(this.model);
  }

  protected override onDeviceLost(): void {
    this.renderer = null;
    this.#tess = {};
    this.flat = null;
    this.cageLines = null;
    this.counts = null;
    this.#otherReader = null;
    this.#frameFactors = this.#builtFactors = null;
  }

  /** The surface drawn now: the one asked for, but Phong where the model has no Catmull-Clark
   * tables (refused, or still being built). */
  get shownSurface(): Surface {
    const s = this.params.surface;
    return s === 'catmull-clark' && !this.cc ? 'phong' : s;
  }

  /** What is drawn now: the tessellated surface or the flat cage. */
  get geometry(): GeometrySource | null {
    const s = this.shownSurface;
    return s === 'cage' ? this.flat : this.#tess[s] ?? null;
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

  /** Switch surfaces (Catmull-Clark, Phong, flat cage), building the Catmull-Clark tables first
   * if the model has none yet; the old picture stays up meanwhile. */
  async showSurface(): Promise<void> {
    const model = this.model;
    if (model && this.params.surface === 'catmull-clark' && !this.cc && !this.ccError) {
      const tables = await this.#tablesFor(model);
      if (this.model !== model) return; // another model came meanwhile, with its own tables
      this.cc = tables.cc;
      this.ccError = tables.error;
      setLoading(null);
      if (tables.error) this.#reportFallback(model.title);
    }
    if (this.model && this.renderer) {
      try {
        this.#uploadModel(this.model);
      } catch (e) {
        showToast(`${(e as Error)?.message ?? String(e)}`, { kind: 'error', title: `Could not tessellate ${this.model.title}` });
      }
    }
    this.lastCounts = null;
    this.tessTimes = {};
    this.invalidateGeometry();
    this.updateStats(true);
  }

  /** Build (or take from the cache) the Catmull-Clark tables of `model`, saying so meanwhile. */
  async #tablesFor(model: LoadedModel): Promise<{ cc: CcTables | null; error: string | null }> {
    if (!this.ccTables.has(model.cage)) setLoading('Building subdivision tables…');
    this.buildingTables = true;
    this.updateStats(true);
    try {
      return { cc: await this.ccTables.get(model.cage), error: null };
    } catch (e) {
      return { cc: null, error: (e as Error)?.message ?? String(e) };
    } finally {
      this.buildingTables = false;
    }
  }

  #reportFallback(title: string): void {
    showToast(`${this.ccError}\n\nShowing the Phong surface instead.`, {
      kind: 'info',
      title: `No Catmull-Clark surface for ${title}`,
      timeout: 10_000,
    });
  }

  /** Patch colours are on and there are patches to colour. */
  get patchColours(): boolean {
    return this.params.patches && this.shownSurface === 'catmull-clark';
  }

  /** The legend of the patch colours, with each kind's share of the cage's triangles. */
  updateLegend(): void {
    const legend = document.getElementById('legend');
    if (!legend) return;
    legend.hidden = !this.patchColours;
    if (legend.hidden) return;
    const kinds = this.cc?.data.triKind ?? new Uint8Array();
    const count = [0, 0, 0, 0];
    for (const k of kinds) count[k]++;
    const hex = (c: readonly number[]) => `#${c.map((x) => Math.round(x * 255).toString(16).padStart(2, '0')).join('')}`;
    legend.innerHTML = `<strong>Patches</strong><ul>${PATCH_COLOURS.map(
      (p) => `<li><span class="swatch" style="background:${hex(p.srgb)}"></span>${p.name} <span class="muted">${count[p.kind]}</span></li>`,
    ).join('')}</ul>`;
  }

  protected override isAnimating(): boolean {
    return this.params.spin;
  }

  protected override onCameraChanged(): void {
    if (this.geometry?.dependsOnCamera(this.params)) this.#geometryDirty = true;
    this.#probeCameraMoved = true;
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
    const renderer = this.renderer;
    const geometry = this.geometry;
    if (!renderer || !geometry) return;
    const cam = this.viewCamera(time);
    const m = cameraMatrices(cam, target.width / Math.max(1, target.height));
    const viewProj = m.viewProj as Float32Array;

    // While spinning, adaptive factors follow the moving camera: rebuild every frame.
    if (this.params.spin && geometry.dependsOnCamera(this.params)) this.#geometryDirty = true;
    this.#rebuiltThisFrame = false;
    // The tessellator works in the cage's own space: hand it the camera in model space.
    const modelViewProj = mat4.multiply(mat4.create(), viewProj, this.modelMatrix) as Float32Array;
    const worldToModel = mat4.invert(mat4.create(), this.modelMatrix)!;
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
    if (this.#geometryDirty && geometry.output) {
      if (geometry instanceof TessellatorGeometry) geometry.flatBaseline = this.params.flat;
      geometry.encode(encoder, factors);
      this.#builtFactors = factors;
      this.counts?.copy(encoder, geometry.output.counts);
      this.#geometryDirty = false;
      this.#rebuiltThisFrame = true;
      this.rebuilds++;
    }
    renderer.render(encoder, target, { viewProj, model: this.modelMatrix, eye: m.eye }, {
      wireframe: this.params.wire,
      cage: this.params.cage,
      patchColours: this.patchColours,
    });
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
    const other = this.params.mode === 'fixed' ? 'adaptive' : 'fixed';
    const setting = other === 'fixed' ? `factor ${this.params.factor}` : `LOD ${this.params.lod}`;
    const key = [this.#loadSerial, this.shownSurface, this.params.flat, other, setting].join('|');
    if (key !== this.#probeKey) this.otherCounts = null;
    else if (!(other === 'adaptive' && this.#probeCameraMoved)) return;
    const wait = this.#lastProbeAt + 1000 - performance.now();
    if (key === this.#probeKey && wait > 0) {
      // The camera moved just after a count: count again a little later.
      if (!this.#probeTimer) this.#probeTimer = window.setTimeout(() => {
        this.#probeTimer = 0;
        this.requestFrame();
      }, wait);
      return;
    }
    if (!reader.idle) return;
    const device = this.gpu.device;
    let encoder = device.createCommandEncoder({ label: `count ${other} output` });
    geometry.encode(encoder, { ...frame, mode: other });
    reader.copy(encoder, geometry.output.counts);
    device.queue.submit([encoder.finish()]);
    encoder = device.createCommandEncoder({ label: 'rebuild the drawn output' });
    geometry.encode(encoder, built);
    device.queue.submit([encoder.finish()]);
    this.#probeKey = key;
    this.#probeCameraMoved = false;
    this.#lastProbeAt = performance.now();
    void reader.read().then((counts) => {
      if (!counts || this.#probeKey !== key) return;
      this.otherCounts = { mode: other, setting, counts };
      this.updateStats(true);
    });
  }

  protected override onAfterSubmit(): void {
    const renderer = this.renderer;
    const geometry = this.geometry;
    this.#countOtherMode();
    // One read of the build's timestamps at a time: while one is mapping, later builds (a
    // turntable rebuilds every frame) go untimed rather than map the same buffer twice.
    const readTess = this.#rebuiltThisFrame && !this.#tessTimingInFlight;
    if (readTess) this.#tessTimingInFlight = true;
    // Each read updates the stats on its own: the counts never wait on a timing read (on some
    // drivers a timestamp buffer's map settles late or not at all).
    const quietly = <T>(p: Promise<T> | undefined, fallback: T) => (p ?? Promise.resolve(fallback)).catch(() => fallback);
    void quietly(this.counts?.read(), null).then((counts) => {
      if (counts) this.lastCounts = counts;
      this.updateStats();
    });
    void quietly(renderer?.readTimings(), {}).then((draw) => {
      this.drawTimes = draw;
      this.updateStats();
    });
    if (readTess) {
      void quietly(geometry?.readTimings(), {}).then((tess) => {
        this.#tessTimingInFlight = false;
        if (Object.keys(tess).length) this.tessTimes = tess;
        this.updateStats();
      });
    }
    if (!this.#firstFrameShown && this.model) {
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
    const now = performance.now();
    if (!force && now < this.#statsDue) {
      if (!this.#statsTimer) this.#statsTimer = window.setTimeout(() => {
        this.#statsTimer = 0;
        this.updateStats(true);
      }, this.#statsDue - now);
      return;
    }
    if (this.#statsTimer) {
      window.clearTimeout(this.#statsTimer);
      this.#statsTimer = 0;
    }
    this.#statsDue = now + 250;
    const panel = document.getElementById('stats');
    if (!panel || !this.params.ui) return;
    panel.innerHTML = renderStats({
      model: this.model,
      counts: this.lastCounts,
      vertexCapacity: this.geometry?.output?.vertexCapacity ?? 0,
      triangleCapacity: this.geometry?.output?.triangleCapacity ?? 0,
      source: this.geometry?.kind ?? 'cage',
      surface: {
        shown: this.shownSurface,
        fallback: this.params.surface === 'catmull-clark' ? this.ccError : null,
        building: this.buildingTables,
        kinds: this.cc ? kindCounts(this.cc.data.triKind) : undefined,
        tablesMs: this.cc?.ms,
        tablesWhere: this.cc?.where,
      },
      other: this.otherCounts,
      mode: this.params.mode,
      tessTimes: this.tessTimes,
      drawTimes: this.drawTimes,
      timestamps: this.gpu.timestamps,
      frameMs: this.timing.frameMs,
      jsMs: this.timing.jsMs,
      rebuilds: this.rebuilds,
      adapter: this.gpu.adapterName,
    });
  }

  /** Show a model; on failure keep the current one and say why. */
  async showModel(load: () => Promise<LoadedModel>, what: string, camera?: Partial<Pick<DemoParams, 'yaw' | 'pitch' | 'dist'>>): Promise<boolean> {
    const serial = ++this.#loadSerial;
    setLoading(`Loading ${what}…`);
    let model: LoadedModel;
    let tables: { cc: CcTables | null; error: string | null } = { cc: null, error: null };
    try {
      model = await load();
      if (serial !== this.#loadSerial) return false; // a later request replaced this one
      // The Catmull-Clark tables first (in a worker; the old model stays up meanwhile).
      if (this.params.surface === 'catmull-clark') tables = await this.#tablesFor(model);
      if (serial !== this.#loadSerial) return false;
    } catch (e) {
      setLoading(null);
      const message = e instanceof CageError ? e.message : (e as Error)?.message ?? String(e);
      const kept = this.model ? `\n\nStill showing ${this.model.title}.` : '';
      showToast(message + kept, { kind: 'error', title: `Could not load ${what}` });
      if (!this.model) setPageState('error');
      return false;
    }
    const kept = { cc: this.cc, ccError: this.ccError };
    this.cc = tables.cc;
    this.ccError = tables.error;
    try {
      this.#uploadModel(model);
    } catch (e) {
      setLoading(null);
      showToast(`${(e as Error)?.message ?? String(e)}`, { kind: 'error', title: `Could not tessellate ${what}` });
      this.cc = kept.cc;
      this.ccError = kept.ccError;
      if (this.model) this.#uploadModel(this.model);
      return false;
    }
    if (tables.error) this.#reportFallback(model.title);
    for (const w of model.warnings.slice(0, 3)) console.info(`${model.title}: ${w.line ? `line ${w.line}: ` : ''}${w.message}`);
    const previous = this.model;
    this.model = model;
    this.placeModel(camera);
    this.lastCounts = null;
    this.tessTimes = {};
    this.invalidateGeometry();
    if (previous) setLoading(null);
    this.updateStats(true);
    // The surface was switched to Catmull-Clark while this model loaded without tables.
    if (this.params.surface === 'catmull-clark' && !this.cc && !this.ccError) void this.showSurface();
    return true;
  }

  /** World bounds, light and camera for the current model and up axis. */
  placeModel(camera?: Partial<Pick<DemoParams, 'yaw' | 'pitch' | 'dist'>>): void {
    if (!this.model) return;
    this.modelMatrix = upAxisMatrix(this.params.up) as Float32Array;
    this.bounds = transformBounds(boundsOf(this.model.cage.positions), this.modelMatrix);
    this.renderer!.setBounds(this.bounds);
    this.setCamera(this.#initialCamera(this.bounds, camera));
    this.invalidateGeometry();
  }

  /** Upload `model` (whose tables, if any, are this.cc) for the surface shown; where the
   * Catmull-Clark tessellator refuses it, fall back to Phong (this.ccError says why). */
  #uploadModel(model: LoadedModel): void {
    try {
      this.#upload(model);
    } catch (e) {
      if (this.shownSurface !== 'catmull-clark') throw e;
      this.cc = null;
      this.ccError = (e as Error)?.message ?? String(e);
      this.#upload(model);
      this.#reportFallback(model.title);
    }
  }

  #upload(model: LoadedModel): void {
    const device = this.gpu.device;
    const surface = this.shownSurface;
    this.flat!.setCage(model.cage);
    if (surface !== 'cage') this.#tessellator(surface).setCage(model.cage, surface === 'catmull-clark' ? this.cc!.data : undefined);
    this.renderer!.setMesh(this.geometry!.output, isClosed(model.cage, model.topology));
    this.renderer!.setPatchKinds(surface === 'catmull-clark' ? this.cc!.data.triKind : null);
    this.updateLegend();
    this.cageLines?.vertices.destroy();
    this.cageLines = uploadCageLines(device, model.cage);
    this.renderer!.setCage(this.cageLines);
    if (this.bounds) this.renderer!.setBounds(this.bounds);
    this.invalidateGeometry();
  }

  #initialCamera(bounds: Bounds, p?: Partial<Pick<DemoParams, 'yaw' | 'pitch' | 'dist'>>): OrbitCamera {
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
    if (this.bounds) this.setCamera(this.frameBounds(this.bounds));
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
    reset: () => demo.resetCamera(),
    share: () => {
      const url = demo.shareUrl();
      void navigator.clipboard?.writeText(url).then(
        () => showToast('Link to this view copied.', { timeout: 2500 }),
        () => showToast(url, { title: 'Link to this view' }),
      );
    },
  };
  const options = Object.fromEntries(demo.models.map((m) => [m.label, m.name]));
  const modelFolder = gui.addFolder('Model');
  const picker = modelFolder.add(state, 'model', options).name('cage').onChange((name: string) => {
    p.model = name;
    syncUrl(p);
    void demo.showModel(() => loadModelFromUrl(modelUrl(name), name), name);
  });
  modelFolder.add(p, 'up', { 'Z (project models)': 'z', Y: 'y' }).name('up axis').onChange(() => {
    syncUrl(p);
    demo.placeModel();
  });
  modelFolder.add(state, 'open').name('open an OBJ file…');

  const tess = gui.addFolder('Tessellation');
  const changed = () => {
    syncUrl(p);
    demo.invalidateGeometry();
  };
  tess.add(p, 'surface', { 'Catmull-Clark': 'catmull-clark', Phong: 'phong', 'flat cage': 'cage' }).name('surface').onChange(() => {
    syncUrl(p);
    showFlat();
    void demo.showSurface();
  });
  const flat = tess.add(p, 'flat').name('flat baseline').onChange(changed);
  const showFlat = () => flat.show(p.surface === 'catmull-clark');
  showFlat();
  tess.add(p, 'mode', { adaptive: 'adaptive', fixed: 'fixed' }).name('factors').onChange(() => {
    showMode();
    changed();
  });
  const lod = tess.add(p, 'lod', LOD_RANGE.min, LOD_RANGE.max, 0.05).name('LOD scale').onChange(changed);
  const factor = tess.add(p, 'factor', FACTOR_RANGE.min, FACTOR_RANGE.max, 0.25).name('fixed factor').onChange(changed);
  const showMode = () => {
    lod.show(p.mode === 'adaptive');
    factor.show(p.mode === 'fixed');
  };
  showMode();

  const view = gui.addFolder('View');
  const redraw = () => {
    syncUrl(p);
    demo.requestFrame();
  };
  view.add(p, 'patches').name('patch colours').onChange(() => {
    demo.updateLegend();
    redraw();
  });
  view.add(p, 'wire').name('wireframe').onChange(redraw);
  view.add(p, 'cage').name('cage overlay').onChange(redraw);
  view.add(p, 'spin').name('turntable').onChange(redraw);
  view.add(state, 'reset').name('reset camera');
  view.add(state, 'share').name('copy link to this view');
  if (window.matchMedia('(max-width: 640px)').matches) gui.close();
  return {
    gui,
    showPicked(name: string) {
      state.model = name;
      picker.updateDisplay();
    },
  };
}

function openFile(demo: TessellationDemo): void {
  const input = document.createElement('input');
  input.type = 'file';
  input.accept = '.obj,text/plain';
  input.addEventListener('change', () => {
    const file = input.files?.[0];
    if (file) void demo.showModel(() => loadModelFromFile(file), file.name);
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
    if (file) void demo.showModel(() => loadModelFromFile(file), file.name);
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
  };
  const [started, models] = await Promise.all([demo.start(), fetchModelList()]);
  if (!started) return;
  demo.models = models;

  const name = params.model ?? DEFAULT_MODEL;
  const panel = params.ui ? buildPanel(demo, isModelUrl(name) ? DEFAULT_MODEL : name) : null;
  enableDrop(demo);

  const camera = { yaw: params.yaw, pitch: params.pitch, dist: params.dist };
  if (isModelUrl(name)) {
    await demo.showModel(() => loadModelFromUrl(name, name.split('/').pop() || name), name, camera);
  } else {
    const ok = await demo.showModel(() => loadModelFromUrl(modelUrl(name), name), name, camera);
    if (!ok && name !== DEFAULT_MODEL) await demo.showModel(() => loadModelFromUrl(modelUrl(DEFAULT_MODEL), DEFAULT_MODEL), DEFAULT_MODEL, camera);
    if (!ok) panel?.showPicked(demo.model?.title ?? DEFAULT_MODEL);
  }
}

void main();
