// Displacement in the demo: the project's displaced models draw displaced (and differently with
// `disp=0` and in the UV-seam view) with no console errors; a dropped PNG height map changes the
// picture; a file that is not a PNG, or a map for a model without uvs, gives a clear message
// and keeps the map shown before.
import { expect, test, type Page } from '@playwright/test';
import { PNG } from 'pngjs';
import { heightMapFromFunction } from '../src/mesh/heightmap.ts';
import { encodeHeightPng } from '../src/mesh/heightmap-png.ts';
import { collectErrors, ready } from './helpers.ts';

/** The canvas alone (no panels), once two shots a moment apart agree. */
async function settled(page: Page): Promise<Buffer> {
  let before = await page.locator('#view').screenshot();
  for (let i = 0; i < 40; i++) {
    await page.waitForTimeout(250);
    const again = await page.locator('#view').screenshot();
    if (Buffer.compare(again, before) === 0) return again;
    before = again;
  }
  return before;
}

/** Luminance (0..1) of a PNG screenshot's pixels. */
function luminance(png: Buffer): { width: number; height: number; at: (x: number, y: number) => number } {
  const im = PNG.sync.read(png);
  const at = (x: number, y: number): number => {
    const i = (y * im.width + x) * 4;
    return (0.2126 * im.data[i] + 0.7152 * im.data[i + 1] + 0.0722 * im.data[i + 2]) / 255;
  };
  return { width: im.width, height: im.height, at };
}

// The brick box's front face in its default frame at 800 × 600 (read from the reference frame,
// e2e/__screenshots__/displacement.spec.ts/brick-box-default.png): about 7 courses of bricks,
// a course ~23 pixels high there.
const FRONT = { x0: 250, x1: 460, y0: 262, y1: 428 };

/**
 * Mortar lines: down columns of the front face, the luminance's autocorrelation at a course's
 * height (a peak at lags 15-35 px) and half a course (a trough at 5-14 px: bricks and mortar
 * alternate), and its spread. A face whose bricks do not read (the earlier default: ~10 segments
 * an edge, 0.17 / −0.20) or a flat one (no trough) has neither.
 */
function courses(png: Buffer): { peak: number; trough: number; spread: number } {
  const l = luminance(png);
  const acf = new Array<number>(36).fill(0);
  let spread = 0,
    n = 0;
  for (let x = FRONT.x0; x < FRONT.x1; x += 6) {
    const col: number[] = [];
    for (let y = FRONT.y0; y < FRONT.y1; y++) col.push(l.at(x, y));
    const mean = col.reduce((a, b) => a + b) / col.length;
    const d = col.map((c) => c - mean);
    const variance = Math.max(d.reduce((a, b) => a + b * b, 0) / d.length, 1e-9);
    spread += Math.sqrt(variance);
    n++;
    for (let lag = 1; lag <= 35; lag++) {
      let s = 0;
      for (let i = 0; i + lag < d.length; i++) s += d[i] * d[i + lag];
      acf[lag] += s / ((d.length - lag) * variance);
    }
  }
  const at = (lag: number) => acf[lag] / n;
  let peak = -1,
    trough = 1;
  for (let lag = 15; lag <= 35; lag++) peak = Math.max(peak, at(lag));
  for (let lag = 5; lag < 15; lag++) trough = Math.min(trough, at(lag));
  return { peak, trough, spread: spread / n };
}

/**
 * Saw teeth: the share of the front face's pixels where the luminance turns up and down again
 * from one pixel to the next (two steps over 0.04 of opposite sign), along rows and along
 * columns together. An edge or a shadow's boundary is one step; teeth along a bevel, or combs
 * at a joint, are many: the earlier default had 0.043, this frame 0.013 (fixed factor 32, 2.7
 * texels a segment on this cage, under-samples the bevels: 0.046).
 */
function teeth(png: Buffer): number {
  const l = luminance(png);
  let turns = 0,
    n = 0;
  const turn = (a: number, b: number) => Math.abs(a) > 0.04 && Math.abs(b) > 0.04 && a * b < 0;
  for (let y = FRONT.y0; y < FRONT.y1; y++)
    for (let x = FRONT.x0; x < FRONT.x1; x++) {
      const c = l.at(x, y);
      if (turn(c - l.at(x - 1, y), l.at(x + 1, y) - c)) turns++;
      if (turn(c - l.at(x, y - 1), l.at(x, y + 1) - c)) turns++;
      n++;
    }
  return turns / n;
}

/** Drop bytes as a file named `name` on the page. */
async function dropBytes(page: Page, name: string, bytes: Uint8Array, type: string): Promise<void> {
  const dataTransfer = await page.evaluateHandle(
    ({ name, data, type }) => {
      const dt = new DataTransfer();
      dt.items.add(new File([Uint8Array.from(data)], name, { type }));
      return dt;
    },
    { name, data: [...bytes], type },
  );
  await page.dispatchEvent('body', 'dragenter', { dataTransfer });
  await page.dispatchEvent('body', 'drop', { dataTransfer });
}

test('the brick box draws displaced; disp=0 and the UV-seam view change the picture', async ({ page }) => {
  test.setTimeout(180_000);
  const errors = collectErrors(page);
  const shot = async (query: string) => {
    await page.goto(`/?model=brick-box&mode=fixed&factor=8&t=0&ui=0${query}`);
    await ready(page);
    return settled(page);
  };
  const displaced = await shot('');
  const flat = await shot('&disp=0');
  const seams = await shot('&seams=1');
  expect(Buffer.compare(displaced, flat)).not.toBe(0);
  expect(Buffer.compare(displaced, seams)).not.toBe(0);
  expect(errors).toEqual([]);
});

test('the brick box at its default view and LOD: the mortar lines read and no saw teeth, against its reference frame', async ({ page }) => {
  test.setTimeout(180_000);
  const errors = collectErrors(page);
  await page.goto('/?model=brick-box&t=0&ui=0');
  await ready(page);
  const frame = await settled(page);
  const { width, height } = luminance(frame);
  expect([width, height]).toEqual([800, 600]);
  const bricks = courses(frame);
  const saw = teeth(frame);
  await page.goto('/?model=brick-box&t=0&ui=0&disp=0');
  await ready(page);
  const flat = courses(await settled(page));
  console.log('brick box default view', { bricks, flat, teeth: saw });
  expect(bricks.peak).toBeGreaterThan(0.28);
  expect(bricks.trough).toBeLessThan(-0.28);
  expect(bricks.spread).toBeGreaterThan(2 * flat.spread);
  expect(saw).toBeLessThan(0.022);
  expect(errors).toEqual([]);
  // The frame the face's coordinates were read from (3D on SwiftShader: a small tolerance).
  expect(frame).toMatchSnapshot('brick-box-default.png', { maxDiffPixelRatio: 0.01 });
});

test('a dropped PNG height map changes the picture; a bad file and a model without uvs keep the map with a message', async ({ page }) => {
  test.setTimeout(180_000);
  const errors = collectErrors(page);
  await page.goto('/?model=creature-wrinkles&mode=fixed&factor=8&t=0&ui=0');
  await ready(page);
  const before = await settled(page);
  // Stripes, 8-bit, 64 × 64.
  const png = encodeHeightPng(heightMapFromFunction(64, 64, 8, (u) => 0.5 + 0.5 * Math.sin(40 * Math.PI * u)));
  await dropBytes(page, 'stripes.png', png, 'image/png');
  await expect(page.getByText('stripes.png: 64×64, 8-bit')).toBeVisible();
  // Toasts lie over the canvas: the pictures are taken without them.
  const noToasts = () => page.locator('.toast').evaluateAll((ts) => ts.forEach((t) => t.remove()));
  await noToasts();
  await expect.poll(async () => Buffer.compare(await settled(page), before)).not.toBe(0);
  const striped = await settled(page);

  await dropBytes(page, 'bad.png', new TextEncoder().encode('this is not a png'), 'image/png');
  const toast = page.getByTestId('toast-error');
  await expect(toast).toContainText('Cannot use bad.png');
  await expect(toast).toContainText('kept');
  await noToasts();
  expect(Buffer.compare(await settled(page), striped)).toBe(0);

  // The plain creature has no uvs.
  await page.goto('/?model=creature&mode=fixed&factor=8&t=0&ui=0');
  await ready(page);
  await dropBytes(page, 'stripes.png', png, 'image/png');
  await expect(page.getByTestId('toast-error')).toContainText('no texture coordinates');
  expect(errors).toEqual([]);
});
