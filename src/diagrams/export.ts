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

export async function exportWebm(src: AnimationSource, palette: Palette, onProgress: Progress, fps = 30, scale = 1.5): Promise<Blob> {
  const { Output, WebMOutputFormat, BufferTarget, CanvasSource, QUALITY_HIGH, canEncodeVideo } = await import('mediabunny');
  const first = src.frameAt(src.start);
  const { canvas, ctx, w, h } = canvasFor(first, scale);
  if (!(await canEncodeVideo('vp9', { width: w, height: h })))
    throw new Error('this browser cannot encode VP9 video (WebCodecs); try the GIF export');
  const output = new Output({ format: new WebMOutputFormat(), target: new BufferTarget() });
  const source = new CanvasSource(canvas, { codec: 'vp9', bitrate: QUALITY_HIGH });
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

export async function exportGif(src: AnimationSource, palette: Palette, onProgress: Progress, fps = 20, scale = 1): Promise<Blob> {
  const { GIFEncoder, quantize, applyPalette } = await import('gifenc');
  const first = src.frameAt(src.start);
  const { ctx, w, h } = canvasFor(first, scale);
  const gif = GIFEncoder();
  const n = Math.max(1, Math.round(Math.min(src.length, MAX_CLIP_SECONDS) * fps));
  const delay = Math.round(1000 / fps);
  for (let i = 0; i < n; i++) {
    drawScene(ctx, src.frameAt(src.start + i / fps), palette, scale);
    const { data } = ctx.getImageData(0, 0, w, h);
    const pal = quantize(data, 128);
    gif.writeFrame(applyPalette(data, pal), w, h, { palette: pal, delay });
    onProgress(i + 1, n);
    if (i % 8 === 7) await new Promise((r) => setTimeout(r, 0)); // keep the page responsive
  }
  gif.finish();
  return new Blob([gif.bytes() as Uint8Array<ArrayBuffer>], { type: 'image/gif' });
}
