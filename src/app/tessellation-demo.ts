/**
 * The demo: a cage, tessellated on the GPU (the Catmull-Clark limit surface, or Phong
 * tessellation), drawn lit and shadowed with optional wireframe, cage overlay and patch colours.
 * The geometry is rebuilt only when the model, the factors or (in adaptive mode) the camera
 * change; every other frame draws the stored buffers again. The Catmull-Clark data (topology only)
 * is prepared on the CPU once per model (cc-tables.ts); the GPU builds the patches every frame.
 *
 * What is drawn and the load flow that changes it are the scene's (demo-scene.ts), the passes of
 * each mode (compute, instanced, split, comparison, error views) the mode's (modes/); this file
 * sets up its frames and encodes their builds, reads back the counts and timings, and keeps the
 * stats and the legend. The page's entry is main.ts, its panel panel.ts.
 */
import { mat4 } from 'gl-matrix';
import { cameraMatrices, transformPoint, type OrbitCamera } from '../gpu/render/camera.ts';
import type { FactorParams } from '../gpu/contract/tessellated-mesh.ts';
import { CountsReader, type MeshCounts } from './counts.ts';
import { TessellatorGeometry, type GeometrySource } from './geometry.ts';
import type { LoadedModel } from './models.ts';
import type { CompareSurface, DemoParams } from './params.ts';
import { factorRuleLevels, type LevelParams } from '../gpu/instanced/instanced-options.ts';
import { OtherModeProbe } from './other-mode.ts';
import { renderStats } from './stats.ts';
import { TrailingThrottle } from './throttle.ts';
import { setLoading, setPageState } from './ui.ts';
import { DemoScene } from './demo-scene.ts';
import { BuildStaleness, type FramePlan } from './build-staleness.ts';
import type { Builds } from './modes/mode.ts';

/** Turntable speed, radians per second. */
const SPIN_SPEED = 0.35;

export class TessellationDemo extends DemoScene {
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
  /** Which builds are stale (src/app/build-staleness.ts). */
  readonly #staleness = new BuildStaleness();
  /** A build's counts still to be copied for reading back. */
  #countsOwed = false;
  #rebuiltThisFrame = false;
  /**
   * Whose figures the stats show. Every drawn build takes the next serial; the counts and the
   * build's timings carry the serial of the build they were read from, so a figure of an older
   * build (the new one still on the GPU, or its read in flight) is marked as such, never passed
   * off as the new one's.
   */
  #buildSerial = 0;
  #countsCopiedFor = 0;
  #countsFor = 0;
  #tessTimesFor = 0;
  /** A read of the build's (or the frames') timestamps is running: later ones are read after it. */
  #tessRead = { reading: false };
  #drawRead = { reading: false };
  /** The stats panel is redrawn at most every 250 ms (see updateStats). */
  readonly #statsThrottle = new TrailingThrottle(() => this.#renderStats(), 250, {
    now: () => performance.now(),
    setTimeout: (fn, ms) => window.setTimeout(fn, ms),
    clearTimeout: (id) => window.clearTimeout(id),
  });
  #firstFrameShown = false;

  /** The counts of the drawn build, read back for the stats. */
  #counts: CountsReader | null = null;

  protected override async onInit(): Promise<void> {
    const device = this.gpu.device;
    this.#counts = new CountsReader(device);
    this.#otherReader = new CountsReader(device);
    this.#otherMode.reset();
    // The scene's objects, then the current model uploaded to the new device.
    await super.onInit();
  }

  protected override onDeviceLost(): void {
    super.onDeviceLost();
    this.#counts = null;
    this.#otherReader = null;
    this.#frameFactors = this.#builtFactors = null;
  }

  /** The comparison's surface (the panel, the URL); null: off. */
  setCompare(surface: CompareSurface | null): void {
    this.params.compare = surface;
    this.compare.reset();
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

  /** The instanced tessellator's flat shading (the panel, the URL). */
  setInstancedFlat(flat: boolean): void {
    this.params.flatShade = flat;
    this.instanced.view?.tess.setFlatShading(flat);
    this.requestFrame();
  }

  /** The instanced tessellator's surface (the panel, the URL): Phong or an ACC scheme. */
  setInstancedSurface(surface: DemoParams['instSurface']): void {
    this.params.instSurface = surface;
    this.syncDrawer(this.model, this.shownSurface);
    this.updateLegend();
    this.invalidateGeometry();
    this.updateStats(true);
  }

  /** Turn the split view on or off (the panel, the URL). */
  setSplit(split: boolean): void {
    this.params.split = split;
    this.syncDrawer(this.model, this.shownSurface);
    this.updateLegend();
    this.invalidateGeometry();
    this.updateStats(true);
  }

  /** Switch tessellators (the panel, the URL): the same model, camera and settings. */
  setTessellator(kind: DemoParams['tessellator']): void {
    this.params.tessellator = kind;
    this.syncDrawer(this.model, this.shownSurface);
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

  /** The legend, the mode's: the patch colours (each kind's share of the cage's triangles) or the
   * error views' colour bar; hidden when it has none. */
  updateLegend(): void {
    const legend = document.getElementById('legend');
    if (!legend) return;
    const html = this.mode.legend();
    legend.hidden = html === null;
    if (html !== null) legend.innerHTML = html;
  }

  protected override isAnimating(): boolean {
    return this.params.spin;
  }

  protected override onCameraChanged(): void {
    this.#staleness.cameraMoved(this.geometry?.dependsOnCamera(this.params) ?? false);
    this.#otherMode.cameraMoved();
  }

  /** Factors or model changed: rebuild at the next frame. */
  invalidateGeometry(): void {
    this.#staleness.invalidate();
    this.requestFrame();
  }

  /** The split and comparison views centre the model on their divider. */
  protected override framesAroundPanel(): boolean {
    return !this.params.split && this.params.compare === null;
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
    const m = cameraMatrices(cam, target.width / Math.max(1, target.height), this.lensShift());
    const viewProj = m.viewProj as Float32Array;

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
    // The mode's builds, then its passes (src/app/modes/).
    const mode = this.mode;
    const plan = this.#build(encoder, geometry, mode.builds(), factors);
    mode.frame(encoder, {
      renderer,
      target,
      geometry,
      factors,
      plan,
      view: { viewProj, model: this.modelMatrix, eye: m.eye },
      options: {
        wireframe: this.params.wire,
        cage: this.params.cage || this.params.seams,
        patchColours: mode.patchColours(),
        material: this.params.material,
      },
      heat: this.params.errorView === 'off' ? null : { view: this.params.errorView, range: this.errorRange },
      measure: (enc, measured, compareRebuilt) => this.#measure(enc, measured, compareRebuilt, factors),
      bindHeat: (pass) => this.bindHeat(renderer, pass),
      countBuild: () => this.#rebuilds++,
    });
  }

  /** What the frame builds (`builds`: the mode's), as the staleness rule says: the instanced
   * tessellator's level pass (else the copy of its owed counts), the compute tessellator's build
   * and the copy of its counts. */
  #build(encoder: GPUCommandEncoder, geometry: GeometrySource, builds: Builds, factors: FactorParams): FramePlan {
    const instanced = builds.instanced;
    const plan = this.#staleness.plan({
      spin: this.params.spin,
      dependsOnCamera: geometry.dependsOnCamera(this.params),
      adaptive: this.params.mode === 'adaptive',
      instanced: instanced !== null,
      computeDrawn: builds.compute,
      hasOutput: !!geometry.output,
    });
    this.#rebuiltThisFrame = plan.build;
    if (instanced) {
      // The instanced tessellator draws: its level pass when the levels may have changed.
      if (plan.levels) {
        instanced.encode(encoder, this.#instancedLevels(factors));
        this.#rebuilds++;
      } else instanced.copyIfOwed(encoder);
    }
    if (plan.build) {
      if (geometry instanceof TessellatorGeometry) geometry.flatBaseline = this.params.flat;
      geometry.encode(encoder, factors);
      this.#builtFactors = factors;
      this.#countsOwed = true;
      this.#buildSerial++;
      // The stats count tessellator builds; the flat cage's (drawn meanwhile while a surface is
      // prepared) encodes nothing.
      if (geometry instanceof TessellatorGeometry) this.#rebuilds++;
    }
    // The counts of the latest build, copied once the reader is free: a copy skipped because a
    // read was still in flight would leave the stats' output row at "…" until the next rebuild
    // (and the demo draws on demand: there may be none).
    if (builds.compute && this.#countsOwed && geometry.output && this.#counts?.idle) {
      this.#counts.copy(encoder, geometry.output.counts);
      this.#countsOwed = false;
      this.#countsCopiedFor = this.#buildSerial;
    }
    return plan;
  }

  /** The error passes of `measured` (a mode's: the left or only surface, the comparison's right
   * half), after the builds they measure (and the first time, for a new pass); the others go. */
  #measure(
    encoder: GPUCommandEncoder,
    measured: readonly [TessellatorGeometry | null, TessellatorGeometry | null],
    compareRebuilt: boolean,
    factors: FactorParams,
  ): void {
    const errors = this.errors;
    const model = this.model;
    errors?.retain(measured);
    const tables = model && measured.some(Boolean) ? this.tables.get(model.cage) : null;
    if (!errors || !model || !tables || typeof tables === 'string') return;
    measured.forEach((g, i) => {
      if (g && errors.passFor(g, model.cage, tables)) errors.encode(encoder, g, i ? compareRebuilt : this.#rebuiltThisFrame, factors);
    });
  }

  /**
   * The stats' other factor mode (fixed while adaptive is drawn, and the reverse): after this
   * frame, one extra build in that mode whose counts are read back, then the drawn build again
   * (separate submissions: each build writes the tessellator's parameters with writeBuffer).
   * Redone when the model, surface, flat baseline or the other mode's setting change, and, for
   * adaptive, at most once a second while the camera moves. Its timing is never what the stats
   * read: the rebuild of the drawn output that follows it is the newer one (the stats read the
   * newest build's timestamps, src/gpu/device/timestamp-ring.ts).
   */
  #countOtherMode(): void {
    const geometry = this.geometry;
    const reader = this.#otherReader;
    const frame = this.#frameFactors;
    const built = this.#builtFactors;
    if (!(geometry instanceof TessellatorGeometry) || !geometry.output || !reader || !frame || !built || !this.model) return;
    if (this.mode.instanced) return;
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
    this.#countOtherMode();
    // Each read updates the stats on its own: the counts never wait on a timing read (on some
    // drivers a timestamp buffer's map settles late or not at all).
    const quietly = <T>(p: Promise<T> | undefined, fallback: T) => (p ?? Promise.resolve(fallback)).catch(() => fallback);
    // The counts' map is asked for first, and the timing maps only once it has settled: a
    // timestamp buffer whose map comes back late cannot hold the counts behind it (Debian's
    // Chromium 156 on SwiftShader kept the output row at "…" so). A timing map that never comes
    // back is cancelled after a deadline and timing stops (src/gpu/device/map-within.ts).
    const copiedFor = this.#countsCopiedFor;
    const countsRead = quietly(this.#counts?.read(), null).then((counts) => {
      if (counts) {
        this.#lastCounts = counts;
        this.#countsFor = copiedFor;
      }
      this.updateStats();
      if (this.#countsOwed) this.requestFrame();
    });
    if (this.instanced.view && this.mode.instanced) {
      const view = this.instanced.view;
      void quietly(view.read(), null).then((counts) => {
        if (counts) this.instanced.counts = counts;
        this.updateStats();
        if (view.owed) this.requestFrame();
      });
    }
    if (this.errors) {
      const errors = this.errors;
      void quietly(errors.read(), false).then((changed) => {
        if (changed) {
          this.updateStats();
          this.updateLegend();
        }
        if (errors.copyOwed) this.requestFrame();
      });
    }
    void countsRead.then(() => this.#readDrawTimes());
    if (this.#rebuiltThisFrame) void countsRead.then(() => this.#readTessTimes());
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

  /** The newest build's timestamps (kept with the build they time). */
  #readTessTimes(): Promise<void> {
    return this.#readNewest(
      this.#tessRead,
      () => this.geometry,
      (times, serial) => {
        if (Object.keys(times).length) {
          this.#tessTimes = times;
          this.#tessTimesFor = serial;
        }
      },
    );
  }

  /** The newest frame's draw timestamps. */
  #readDrawTimes(): Promise<void> {
    return this.#readNewest(
      this.#drawRead,
      () => this.renderer,
      (times) => {
        this.#drawTimes = times;
      },
    );
  }

  /**
   * One read at a time per kind (`flag`): `current()`'s newest timestamps, handed to `take` with
   * the build serial they were asked at, then again while a newer submission's wait (builds and
   * frames submitted meanwhile are timed into the ring, src/gpu/device/timestamp-ring.ts, and
   * read after it). The demo draws on demand: without the second read, a build landing during a
   * read kept the older build's figures on screen until some later build.
   */
  async #readNewest<S extends { readTimings(): Promise<Record<string, number>>; readonly timingUnread?: boolean }>(
    flag: { reading: boolean },
    current: () => S | null,
    take: (times: Record<string, number>, serial: number) => void,
  ): Promise<void> {
    if (flag.reading) return;
    flag.reading = true;
    try {
      for (;;) {
        const source = current();
        if (!source) break;
        const serial = this.#buildSerial;
        const times = await source.readTimings().catch(() => ({}) as Record<string, number>);
        if (source !== current()) break;
        take(times, serial);
        this.updateStats();
        if (!source.timingUnread) break;
      }
    } finally {
      flag.reading = false;
    }
  }

  protected override onIdle(): void {
    this.updateStats();
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
    // The compact view's button (the panel is rewritten below; the listener and the class stay).
    panel.onclick ??= (e) => {
      if ((e.target as Element).closest('.stats-toggle')) panel.classList.toggle('expanded');
    };
    const mode = this.mode;
    const { compare, instanced } = mode.stats();
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
        note: this.geometry instanceof TessellatorGeometry ? (this.geometry.tessellatedCage?.note ?? null) : null,
      },
      other: this.#otherMode.counts,
      mode: this.params.mode,
      tessTimes: this.#tessTimes,
      tessTimesStale: this.#tessTimesFor !== this.#buildSerial,
      countsStale: this.#countsFor !== this.#buildSerial,
      drawTimes: this.#drawTimes,
      timestamps: this.gpu.timestamps,
      timingStalled: !!(this.renderer?.timingStalled || this.geometry?.timingStalled),
      frameMs: this.timing.frameMs,
      jsMs: this.timing.jsMs,
      rebuilds: this.#rebuilds,
      adapter: this.gpu.adapterName,
      memory: this.memory.counts,
      clamps: this.clamps,
      errors: mode.errorStats(),
      compare,
      instanced,
    });
  }

  protected override onModelShown(previous: LoadedModel | null): void {
    // Another model: no figure of the previous one stays on screen.
    this.#lastCounts = null;
    this.#tessTimes = {};
    this.#drawTimes = {};
    this.updateLegend();
    this.invalidateGeometry();
    // The first model's message stays until its first frame is on screen (onAfterSubmit).
    if (previous) setLoading(null);
    this.updateStats(true);
  }
}

function kindCounts(kinds: Uint8Array): [number, number, number, number] {
  const n: [number, number, number, number] = [0, 0, 0, 0];
  for (const k of kinds) n[k & 3]++;
  return n;
}
