/**
 * The small base every WebGPU page of the site can share (after toji's TinyWebGpuDemo): it owns
 * the canvas and its HiDPI size, the device (and its recovery after a loss), the orbit camera
 * and its input, the frame loop and its timing. A page overrides onInit / onFrame.
 *
 * Frames are drawn on demand: only when something changed (camera, size, settings) or while
 * animating. `frozenTime` (the URL's ?t=) pins the clock for deterministic screenshots.
 */
import { SRGB_TARGET_FORMAT, SrgbBlit } from '../gpu/render/srgb-blit.ts';
import { createGpu, GpuUnavailableError, type GpuContext, type LimitName } from '../gpu/device/device.ts';
import { GpuMemory, trackDevice } from '../gpu/device/tracked-device.ts';
import { dolly, fitOrbit, orbit, type Bounds, type OrbitCamera } from '../gpu/render/camera.ts';
import { setLoading, setPageState, showFatal, showToast } from './ui.ts';

export interface DemoBaseOptions {
  /** Seconds: render as if at this time, and never advance the clock. */
  frozenTime: number | null;
}

export interface FrameTiming {
  /** Milliseconds between the last frames drawn (0 when idle). */
  frameMs: number;
  /** Milliseconds of JavaScript spent encoding a frame. */
  jsMs: number;
}

const SAMPLES = 20;
const ORBIT_RADIANS_PER_PIXEL = 0.008;
const KEY_ORBIT_STEP = (5 * Math.PI) / 180;

export abstract class DemoBase {
  readonly canvas: HTMLCanvasElement;
  readonly frozenTime: number | null;
  /** The device context; its `device` counts every buffer and texture made through it in
   * `memory` (src/gpu/device/tracked-device.ts), so everything the page allocates is on the ledger. */
  gpu!: GpuContext;
  /** The live GPU buffers and textures of the current device (a new ledger per device). */
  memory = new GpuMemory();
  context!: GPUCanvasContext;
  /** The canvas texture's format, and the view format the renderer draws with (its -srgb twin). */
  /** Compatibility mode: the -srgb picture drawn, then copied to the canvas (null in core). */
  #blit: SrgbBlit | null = null;
  canvasFormat!: GPUTextureFormat;
  renderFormat!: GPUTextureFormat;
  camera: OrbitCamera | null = null;
  readonly timing: FrameTiming = { frameMs: 0, jsMs: 0 };

  #dirty = true;
  #lastFrameAt = 0;
  #frameSamples: number[] = [];
  #jsSamples: number[] = [];
  #startedAt = performance.now();
  #recovering = false;
  #pointers = new Map<number, { x: number; y: number }>();

  constructor(canvas: HTMLCanvasElement, options: DemoBaseOptions) {
    this.canvas = canvas;
    this.frozenTime = options.frozenTime;
  }

  /** Called with each new device (the first, and again after a device loss): create GPU resources. */
  protected abstract onInit(): Promise<void> | void;
  /** Encode one frame into `target` (the canvas's current texture). */
  protected abstract onFrame(encoder: GPUCommandEncoder, target: GPUTexture, time: number): void;
  /** After the frame's commands were submitted: read back timings and counters. */
  protected onAfterSubmit(): void {}
  /** The frames stopped (nothing to draw): the frame time went to 0 ("idle"). */
  protected onIdle(): void {}
  /** The user moved the camera. */
  protected onCameraChanged(): void {}
  /** Release GPU resources of a lost device (they are garbage, but hold JS references). */
  protected onDeviceLost(): void {}
  /** Limits the page would like (requested up to what the adapter has; see GpuContext.clamps). */
  protected wantedLimits(): Partial<Record<LimitName, number>> {
    return {};
  }
  /** Whether to keep drawing frames without further input (animation). */
  protected isAnimating(): boolean {
    return false;
  }

  /** Seconds since start, or the frozen time. */
  get time(): number {
    return this.frozenTime ?? (performance.now() - this.#startedAt) / 1000;
  }

  get aspect(): number {
    return this.canvas.width / Math.max(1, this.canvas.height);
  }

  async start(): Promise<boolean> {
    setLoading('Starting WebGPU…');
    try {
      await this.#initDevice();
    } catch (e) {
      if (e instanceof GpuUnavailableError) showFatal(e.problem, e.message);
      else showFatal('other', (e as Error)?.stack ?? String(e));
      return false;
    }
    this.#observeSize();
    this.#bindInput();
    const loop = () => {
      this.#tick();
      requestAnimationFrame(loop);
    };
    requestAnimationFrame(loop);
    return true;
  }

  /** Draw a frame at the next animation frame. */
  requestFrame(): void {
    this.#dirty = true;
  }

  /** Frame the model, or restore an explicit camera. */
  setCamera(camera: OrbitCamera): void {
    this.camera = camera;
    this.onCameraChanged();
    this.requestFrame();
  }

  frameBounds(bounds: Bounds): OrbitCamera {
    return fitOrbit(bounds, this.aspect * (1 - this.panelCover()));
  }

  /** Whether the model is framed in the part of the canvas the panel leaves free (a mode whose
   * picture is centred on the canvas, as a split view's divider is, says no). */
  protected framesAroundPanel(): boolean {
    return true;
  }

  /**
   * The fraction of the canvas's width that the control panel covers at its right: 0 where it
   * covers nothing worth framing around (hidden, closed, a window under 900 px wide, where it
   * lies across the top). At 1000 px the open panel hid a third of the creature.
   */
  panelCover(): number {
    if (!this.framesAroundPanel()) return 0;
    const panel = document.querySelector('.lil-gui.panel');
    // Closed by its title: aria-expanded is set at the click (the lil-closed class a frame later).
    if (!panel || panel.querySelector(':scope > .lil-title')?.getAttribute('aria-expanded') === 'false') return 0;
    const canvas = this.canvas.getBoundingClientRect();
    const r = panel.getBoundingClientRect();
    if (canvas.width < 900 || r.width === 0 || r.left < canvas.left + canvas.width / 2) return 0;
    return Math.min(0.5, Math.max(0, (canvas.right - r.left) / canvas.width));
  }

  /** The lens shift (clip units, camera.ts cameraMatrices) that centres the model in the canvas
   * left of the panel: half the covered width. */
  lensShift(): number {
    return -this.panelCover();
  }

  async #initDevice(): Promise<void> {
    const gpu = await createGpu({
      gpu: navigator.gpu,
      wantedLimits: this.wantedLimits(),
      onLost: (info) => void this.#recover(info),
      onUncapturedError: (error) => {
        console.error(`WebGPU ${error.constructor.name}: ${error.message}`);
        showToast(error.message, { kind: 'error', title: 'WebGPU error' });
      },
    });
    const tracked = trackDevice(gpu.device);
    this.memory = tracked.memory;
    this.gpu = { ...gpu, device: tracked.device };
    this.context = this.canvas.getContext('webgpu') as GPUCanvasContext;
    this.canvasFormat = navigator.gpu.getPreferredCanvasFormat();
    // Draw through an -srgb view: lighting stays linear, blending and MSAA resolve happen in
    // linear space, and the canvas (whose own format cannot be -srgb) stores encoded values.
    // Compatibility mode allows no view formats: draw into an -srgb picture and copy it to the
    // canvas with the encoding done in a shader (src/gpu/render/srgb-blit.ts).
    this.#blit?.destroy();
    this.#blit = gpu.compatibility ? new SrgbBlit(this.gpu.device, this.canvasFormat) : null;
    this.renderFormat = this.#blit ? SRGB_TARGET_FORMAT : (`${this.canvasFormat}-srgb` as GPUTextureFormat);
    this.context.configure({
      // The platform checks that this is a real GPUDevice: not the counting stand-in.
      device: tracked.real,
      format: this.canvasFormat,
      viewFormats: this.#blit ? [] : [this.renderFormat],
      alphaMode: 'opaque',
    });
    await this.onInit();
    this.requestFrame();
  }

  async #recover(info: GPUDeviceLostInfo): Promise<void> {
    if (this.#recovering) return;
    this.#recovering = true;
    console.warn(`WebGPU device lost (${info.reason}): ${info.message}`);
    setPageState('lost');
    showToast(`${info.message || 'no message'} — recreating the device and its resources.`, {
      kind: 'info',
      title: 'GPU device lost',
      timeout: 5000,
    });
    this.onDeviceLost();
    for (let attempt = 0; attempt < 3; attempt++) {
      try {
        this.context.unconfigure();
        await this.#initDevice();
        this.#recovering = false;
        setPageState('ready');
        return;
      } catch (e) {
        console.error('device recovery failed', e);
        await new Promise((r) => setTimeout(r, 250 * (attempt + 1)));
      }
    }
    showFatal('lost', info.message);
  }

  #tick(): void {
    // A hidden tab draws nothing (browsers mostly stop animation frames anyway); the frame owed
    // stays owed and is drawn when the tab is shown again (see #bindInput's visibilitychange).
    if (this.#recovering || !this.camera || document.visibilityState === 'hidden') return;
    if (!this.#dirty && !(this.frozenTime === null && this.isAnimating())) {
      // Idle: the frame time is of frames drawn in a row, so none is shown now (it used to keep
      // the last figure while nothing was drawn).
      if (this.#lastFrameAt) {
        this.#lastFrameAt = 0;
        this.#frameSamples.length = 0;
        this.timing.frameMs = 0;
        this.onIdle();
      }
      return;
    }
    this.#dirty = false;
    const now = performance.now();
    if (this.#lastFrameAt) push(this.#frameSamples, now - this.#lastFrameAt);
    this.#lastFrameAt = now;

    const device = this.gpu.device;
    const encoder = device.createCommandEncoder({ label: 'frame encoder' });
    const canvasTexture = this.context.getCurrentTexture();
    const target = this.#blit ? this.#blit.target(canvasTexture.width, canvasTexture.height) : canvasTexture;
    this.onFrame(encoder, target, this.time);
    this.#blit?.encode(encoder, canvasTexture);
    device.queue.submit([encoder.finish()]);
    push(this.#jsSamples, performance.now() - now);
    this.timing.frameMs = average(this.#frameSamples);
    this.timing.jsMs = average(this.#jsSamples);
    this.onAfterSubmit();
  }

  #observeSize(): void {
    const maxSize = this.gpu.device.limits.maxTextureDimension2D;
    // Size the canvas now: the first frame (and the camera framed for its aspect) must not
    // depend on when the observer's first callback comes.
    const dpr = window.devicePixelRatio || 1;
    this.canvas.width = Math.max(1, Math.min(Math.round(this.canvas.clientWidth * dpr), maxSize));
    this.canvas.height = Math.max(1, Math.min(Math.round(this.canvas.clientHeight * dpr), maxSize));
    const observer = new ResizeObserver(([entry]) => {
      // Device pixels when the browser reports them exactly; otherwise CSS pixels × DPR.
      const box = entry.devicePixelContentBoxSize?.[0];
      const dpr = window.devicePixelRatio || 1;
      const width = box ? box.inlineSize : Math.round(entry.contentBoxSize[0].inlineSize * dpr);
      const height = box ? box.blockSize : Math.round(entry.contentBoxSize[0].blockSize * dpr);
      this.canvas.width = Math.max(1, Math.min(width, maxSize));
      this.canvas.height = Math.max(1, Math.min(height, maxSize));
      this.onCameraChanged();
      this.requestFrame();
    });
    try {
      observer.observe(this.canvas, { box: 'device-pixel-content-box' });
    } catch {
      observer.observe(this.canvas);
    }
  }

  #moveCamera(change: (c: OrbitCamera) => OrbitCamera): void {
    if (!this.camera) return;
    this.camera = change(this.camera);
    this.onCameraChanged();
    this.requestFrame();
  }

  #bindInput(): void {
    const canvas = this.canvas;
    document.addEventListener('visibilitychange', () => {
      if (document.visibilityState === 'visible') {
        // Timings measured across the hidden time would read as one very long frame.
        this.#lastFrameAt = 0;
        this.requestFrame();
      }
    });
    canvas.addEventListener('pointerdown', (e) => {
      canvas.setPointerCapture(e.pointerId);
      this.#pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    });
    const release = (e: PointerEvent) => this.#pointers.delete(e.pointerId);
    canvas.addEventListener('pointerup', release);
    canvas.addEventListener('pointercancel', release);
    canvas.addEventListener('pointermove', (e) => {
      const last = this.#pointers.get(e.pointerId);
      if (!last) return;
      if (this.#pointers.size === 1) {
        const dx = e.clientX - last.x;
        const dy = e.clientY - last.y;
        this.#moveCamera((c) => orbit(c, -dx * ORBIT_RADIANS_PER_PIXEL, dy * ORBIT_RADIANS_PER_PIXEL));
      } else if (this.#pointers.size === 2) {
        // Pinch: zoom by the change of the distance between the two fingers.
        const other = [...this.#pointers.entries()].find(([id]) => id !== e.pointerId)![1];
        const before = Math.hypot(last.x - other.x, last.y - other.y);
        const after = Math.hypot(e.clientX - other.x, e.clientY - other.y);
        if (before > 0 && after > 0) this.#moveCamera((c) => dolly(c, before / after));
      }
      this.#pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    });
    canvas.addEventListener(
      'wheel',
      (e) => {
        e.preventDefault();
        // Lines or pages from some mice; pixels from trackpads.
        const pixels = e.deltaY * (e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? 400 : 1);
        this.#moveCamera((c) => dolly(c, Math.exp(Math.max(-200, Math.min(200, pixels)) * 0.0015)));
      },
      { passive: false },
    );
    window.addEventListener('keydown', (e) => {
      const target = e.target as HTMLElement | null;
      if (target && (target.isContentEditable || /^(INPUT|TEXTAREA|SELECT)$/.test(target.tagName))) return;
      if (e.ctrlKey || e.metaKey || e.altKey) return;
      const moves: Record<string, (c: OrbitCamera) => OrbitCamera> = {
        ArrowLeft: (c) => orbit(c, -KEY_ORBIT_STEP, 0),
        ArrowRight: (c) => orbit(c, KEY_ORBIT_STEP, 0),
        ArrowUp: (c) => orbit(c, 0, KEY_ORBIT_STEP),
        ArrowDown: (c) => orbit(c, 0, -KEY_ORBIT_STEP),
        '+': (c) => dolly(c, 1 / 1.15),
        '=': (c) => dolly(c, 1 / 1.15),
        '-': (c) => dolly(c, 1.15),
        _: (c) => dolly(c, 1.15),
      };
      const move = moves[e.key];
      if (!move) return;
      e.preventDefault();
      this.#moveCamera(move);
    });
  }
}

function push(samples: number[], x: number): void {
  samples.push(x);
  if (samples.length > SAMPLES) samples.shift();
}

function average(samples: number[]): number {
  return samples.length ? samples.reduce((a, b) => a + b, 0) / samples.length : 0;
}
