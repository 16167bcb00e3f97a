/**
 * Static and animated export of a figure, in the browser: PNG (the current frame, 2× pixels),
 * SVG (vector, from the same scene), WebM (VP9, mediabunny over WebCodecs) and GIF (gifenc).
 * The animated exports render one cycle frame by frame from the pure figure function, so they
 * do not depend on the screen's frame rate. The video libraries load only when used.
 */
import { drawScene, sceneToSvg, type Palette, type Scene } from './scene.ts';

export function download(blob: Blob, name: string): void {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  a.rel = 'noopener';
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

function canvasFor(scene: Scene, scale: number): { canvas: HTMLCanvasElement; ctx: CanvasRenderingContext2D; w: number; h: number } {
  // Even sizes: video encoders want them.
  const w = 2 * Math.round((scene.width * scale) / 2);
  const h = 2 * Math.round((scene.height * scale) / 2);
  const canvas = document.createElement('canvas');
  canvas.width = w;
  canvas.height = h;
  const ctx = canvas.getContext('2d', { willReadFrequently: true });
  if (!ctx) throw new Error('2D canvas unavailable');
  return { canvas, ctx, w, h };
}

export async function exportPng(scene: Scene, palette: Palette, scale = 2): Promise<Blob> {
  const { canvas, ctx } = canvasFor(scene, scale);
  drawScene(ctx, scene, palette, scale);
  return new Promise((resolve, reject) => canvas.toBlob((b) => (b ? resolve(b) : reject(new Error('PNG encoding failed'))), 'image/png'));
}

export function exportSvg(scene: Scene, palette: Palette): Blob {
  return new Blob([`<?xml version="1.0" encoding="UTF-8"?>\n${sceneToSvg(scene, palette)}\n`], { type: 'image/svg+xml' });
}

export interface AnimationSource {
  /** The scene at time t (seconds). */
  frameAt(t: number): Scene;
  /** Start and length of the exported clip, seconds. */
  start: number;
  length: number;
}

type Progress = (done: number, total: number) => void;

/** Clips are capped so that a long figure still exports in a few seconds. */
export const MAX_CLIP_SECONDS = 24;

/**
 * The default settings of the animated exports, sized for a blog post: at most 3 MB for every
 * preset (e2e/diagrams.spec.ts measures them all), the clip at most 24 s.
 *  - WebM: the figure's own layout at 1× (760 px wide: a blog column is 650 to 760 px, and the
 *    type is then at its designed size), 24 fps (the factors change slowly; fewer frames leave
 *    more bits to each, and encode faster), and a fixed target of 800 kbit/s: 24 s × 0.8 Mbit/s
 *    = 2.4 MB, leaving room for the encoder overshooting its target. (The quality-driven encoding
 *    this replaces spent up to 6.3 Mbit/s, 16.6 MB, on a triangle figure at 1.5× and 30 fps.)
 *    Flat colours and thin lines encode well at that rate; the meshes stay sharp.
 *  - GIF: 640 px wide (GIF has no compression between frames, so every pixel counts), 10 fps
 *    (GIF delays are whole hundredths of a second, so 10/100 s is exact; 12.5 fps took the
 *    largest preset to 2.9 MB, too close to the budget), one 63-colour palette for the whole
 *    clip (the figures use a dozen colours plus their antialiasing), and every frame after the
 *    first stores only the pixels that changed (the others transparent, which LZW packs into
 *    almost nothing).
 */
export const WEBM_DEFAULTS = { fps: 24, scale: 1, bitrate: 800_000 };
export const GIF_DEFAULTS = { fps: 10, width: 640, colors: 63 };

export async function exportWebm(
  src: AnimationSource,
  palette: Palette,
  onProgress: Progress,
  { fps, scale, bitrate } = WEBM_DEFAULTS,
): Promise<Blob> {
  const { Output, WebMOutputFormat, BufferTarget, CanvasSource, Quality, canEncodeVideo } = await import('mediabunny');
  const first = src.frameAt(src.start);
  const { canvas, ctx, w, h } = canvasFor(first, scale);
  if (!(await canEncodeVideo('vp9', { width: w, height: h })))
    throw new Error('this browser cannot encode VP9 video (WebCodecs); try the GIF export');
  const output = new Output({ format: new WebMOutputFormat(), target: new BufferTarget() });
  const source = new CanvasSource(canvas, { codec: 'vp9', quality: new Quality({ bitrate }) });
  output.addVideoTrack(source, { frameRate: fps });
  await output.start();
  const n = Math.max(1, Math.round(Math.min(src.length, MAX_CLIP_SECONDS) * fps));
  for (let i = 0; i < n; i++) {
    drawScene(ctx, src.frameAt(src.start + i / fps), palette, scale);
    await source.add(i / fps, 1 / fps);
    onProgress(i + 1, n);
  }
  await output.finalize();
  const buf = output.target.buffer;
  if (!buf) throw new Error('no video data');
  return new Blob([buf], { type: 'video/webm' });
}

export async function exportGif(
  src: AnimationSource,
  palette: Palette,
  onProgress: Progress,
  { fps, width, colors } = GIF_DEFAULTS,
): Promise<Blob> {
  const { GIFEncoder, quantize, nearestColorIndex } = await import('gifenc');
  const first = src.frameAt(src.start);
  const scale = width / first.width;
  const { ctx, w, h } = canvasFor(first, scale);
  const n = Math.max(1, Math.round(Math.min(src.length, MAX_CLIP_SECONDS) * fps));
  const pixels = (i: number) => {
    drawScene(ctx, src.frameAt(src.start + i / fps), palette, scale);
    return ctx.getImageData(0, 0, w, h).data;
  };
  // One palette for every frame, from five frames across the clip (a colour that only some
  // frames show, such as a moving point's red, is then in it), so that an unchanged pixel keeps
  // its index and the frames can be stored as differences.
  const samples = [0, 0.25, 0.5, 0.75, 1].map((s) => pixels(Math.round(s * (n - 1))));
  const all = new Uint8ClampedArray(samples.reduce((k, d) => k + d.length, 0));
  samples.forEach((d, k) => all.set(d, k * d.length));
  const pal = quantize(all, colors);
  const clear = pal.length; // one more entry, never drawn: the transparent "unchanged" index
  // Each RGBA value's palette index, found once: a figure has few distinct colours.
  const nearest = new Map<number, number>();
  const gif = GIFEncoder();
  const delay = Math.round(1000 / fps);
  let before: Uint32Array | null = null; // the last frame's RGBA, one word a pixel
  const shown = new Uint8Array(w * h); // the index each pixel shows after the frames so far
  for (let i = 0; i < n; i++) {
    const data = pixels(i);
    const rgba = new Uint32Array(data.buffer, data.byteOffset, w * h);
    const index = new Uint8Array(w * h);
    for (let k = 0; k < index.length; k++) {
      const c = rgba[k];
      if (before && before[k] === c) {
        index[k] = clear;
        continue;
      }
      let j = nearest.get(c);
      if (j === undefined) {
        j = nearestColorIndex(pal, [c & 255, (c >>> 8) & 255, (c >>> 16) & 255]); // little-endian RGBA
        nearest.set(c, j);
      }
      // A new colour with the same index as the pixel shows already is no change either.
      index[k] = before && j === shown[k] ? clear : j;
      shown[k] = j;
    }
    if (!before) gif.writeFrame(index, w, h, { palette: [...pal, [0, 0, 0]], delay });
    // dispose 1: keep the frame before, so that the transparent pixels show it.
    else gif.writeFrame(index, w, h, { delay, transparent: true, transparentIndex: clear, dispose: 1 });
    before = rgba;
    onProgress(i + 1, n);
    if (i % 8 === 7) await new Promise((r) => setTimeout(r, 0)); // keep the page responsive
  }
  gif.finish();
  return new Blob([gif.bytes() as Uint8Array<ArrayBuffer>], { type: 'image/gif' });
}
