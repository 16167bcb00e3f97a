// The demo with the instanced power-of-two tessellator (`?tessellator=instanced`), in headless
// Chromium on SwiftShader: it draws (lit, shadow and wireframe passes, the surface evaluated in
// each) with no console errors, its bucket draw records equal the CPU's count, its stats show
// what it draws per pass, and switching tessellators keeps the page working.
import { expect, test, type Page } from '@playwright/test';
import { PNG } from 'pngjs';
import { HOLED_CUBE, collectErrors, dropFile, ready } from './helpers.ts';

interface Records {
  gpu: number[];
  cpu: number[] | null;
  mode: string;
  counts: { triangles: number; vertices: number; patches: number; levels: [number, number][] };
}

function records(page: Page): Promise<Records | null> {
  return page.evaluate(() =>
    (window as unknown as { tessellab: { instancedRecords(): Promise<Records | null> } }).tessellab.instancedRecords(),
  );
}

const int = (n: number) => new Intl.NumberFormat('en-US').format(n);

test('static level: the bucket draw records equal the CPU count; stats per pass; no console errors', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('/?model=creature&tessellator=instanced&mode=fixed&level=8&t=0');
  await ready(page);
  const r = await records(page);
  expect(r).not.toBeNull();
  expect(r!.mode).toBe('static');
  expect(r!.cpu).not.toBeNull();
  expect(r!.gpu).toEqual(r!.cpu);
  // creature: 556 quad and 16 triangle patches, all at level 8 (8 × 8 × 2 and 8 × 8 triangles).
  expect(r!.counts.patches).toBe(572);
  expect(r!.counts.levels).toEqual([[8, 572]]);
  expect(r!.counts.triangles).toBe(556 * 128 + 16 * 64);
  await expect(page.getByTestId('stats-output')).toContainText(`${int(r!.counts.triangles)} tris`, { timeout: 5_000 });
  await expect(page.getByTestId('stats-output')).toContainText('instanced, static level 8');
  await expect(page.getByTestId('stats-buckets')).toContainText('L8: 572');
  await expect(page.getByTestId('stats-gpu')).not.toHaveText('…', { timeout: 5_000 });
  await expect(page.getByTestId('stats-surface')).toContainText('Phong');
  expect(errors).toEqual([]);
});

test("dynamic LOD (adaptive, the compute tessellator's factor rule): every patch in one bucket, mixed levels, no console errors", async ({
  page,
}) => {
  const errors = collectErrors(page);
  await page.goto('/?model=creature&tessellator=instanced&t=0&lod=2');
  await ready(page);
  const r = await records(page);
  expect(r).not.toBeNull();
  expect(r!.mode).toBe('factor-rule');
  expect(r!.counts.patches).toBe(572);
  // Each record's pattern fields are the pattern table's whatever the view: they equal the
  // static count's (only the instance counts depend on the view).
  const sumInstances = [...Array(14).keys()].reduce((a, b) => a + r!.gpu[5 * b + 1], 0);
  expect(sumInstances).toBe(572);
  expect(r!.counts.levels.length).toBeGreaterThan(1);
  await expect(page.getByTestId('stats-output')).toContainText('dynamic LOD 2', { timeout: 5_000 });
  expect(errors).toEqual([]);
});

test('switching tessellators: compute and instanced on the same model, camera and page', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('/?model=torus&surface=phong&mode=fixed&factor=8&level=8&t=0');
  await ready(page);
  await expect(page.getByTestId('stats-output')).toContainText(`${int(256 * 64)} tris`, { timeout: 5_000 });
  const set = (kind: string) =>
    page.evaluate(
      (k) => (window as unknown as { tessellab: { demo: { setTessellator(k: string): void } } }).tessellab.demo.setTessellator(k),
      kind,
    );
  await set('instanced');
  // Matched settings: level 8 on the torus's 128 quads draws as many triangles as factor 8.
  await expect(page.getByTestId('stats-output')).toContainText(`${int(256 * 64)} tris`, { timeout: 5_000 });
  await expect(page.getByTestId('stats-output')).toContainText('instanced');
  const r = await records(page);
  expect(r!.gpu).toEqual(r!.cpu);
  await set('compute');
  await expect(page.getByTestId('stats-output')).not.toContainText('instanced', { timeout: 5_000 });
  expect(await records(page)).toBeNull();
  expect(errors).toEqual([]);
});

test('split view: compute on the left, instanced on the right, same cage and camera; both counted and timed; no console errors', async ({
  page,
}) => {
  const errors = collectErrors(page);
  await page.goto('/?model=torus&surface=phong&split=1&mode=fixed&factor=8&level=8&t=0');
  await ready(page);
  // Matched settings: the same triangle count on both halves.
  await expect(page.getByTestId('stats-output-compute')).toContainText(`${int(256 * 64)} tris`, { timeout: 5_000 });
  await expect(page.getByTestId('stats-output')).toContainText(`${int(256 * 64)} tris`, { timeout: 5_000 });
  const r = await records(page);
  expect(r!.gpu).toEqual(r!.cpu);
  const timed = await page.evaluate(
    () => (window as unknown as { tessellab: { demo: { gpu: { timestamps: boolean } } } }).tessellab.demo.gpu.timestamps,
  );
  if (timed) {
    await expect(page.getByTestId('stats-gpu-compute')).toContainText(/shadow [\d.<]+ · lit [\d.<]+/, { timeout: 5_000 });
    await expect(page.getByTestId('stats-gpu')).toContainText(/shadow [\d.<]+ · lit [\d.<]+/, { timeout: 5_000 });
  }
  // Each half says which tessellator draws it, with a line between them.
  await expect(page.getByTestId('split-left')).toContainText('compute · Phong');
  await expect(page.getByTestId('split-right')).toContainText('instanced · Phong · static level 8');
  await expect(page.getByTestId('split-divider')).toBeVisible();
  // Both halves show the torus: bright (lit clay) pixels on each side of the canvas's middle.
  const shot = PNG.sync.read(
    await page.locator('#view').screenshot({
      mask: [page.locator('#stats'), page.locator('.lil-gui.panel'), page.locator('.side-label'), page.locator('.side-divider')],
      maskColor: '#000000',
    }),
  );
  const halves = [0, 0];
  for (let y = 0; y < shot.height; y++)
    for (let x = 0; x < shot.width; x++) {
      const k = 4 * (y * shot.width + x);
      if (shot.data[k] + shot.data[k + 1] + shot.data[k + 2] > 400) halves[x < shot.width / 2 ? 0 : 1]++;
    }
  expect(halves[0]).toBeGreaterThan(500);
  expect(halves[1]).toBeGreaterThan(500);
  expect(errors).toEqual([]);
});

test('ACC surfaces: the instanced tessellator draws Gregory ACC, the icosphere refined once, a cube with a hole', async ({ page }) => {
  // Two page loads, each compiling an ACC surface's pipelines on SwiftShader: 25-37 s alone, past
  // the default 60 s once with two workers on two cores (a time budget, not a race).
  test.setTimeout(150_000);
  const errors = collectErrors(page);
  await page.goto('/?model=torus&tessellator=instanced&instsurface=gregory-acc&mode=fixed&level=8&t=0');
  await ready(page);
  await expect(page.getByTestId('stats-surface')).toContainText('Gregory ACC', { timeout: 5_000 });
  await expect(page.getByTestId('stats-output')).toContainText(`${int(256 * 64)} tris`, { timeout: 5_000 });
  const r = await records(page);
  expect(r!.gpu).toEqual(r!.cpu);
  // The icosphere has pentagons: refined once (the same limit), its 230 quads are the patches.
  await page.goto('/?model=icosphere&tessellator=instanced&instsurface=pm-acc&mode=fixed&level=4&t=0');
  await ready(page);
  await expect(page.getByTestId('stats-surface')).toContainText('Pm ACC', { timeout: 5_000 });
  await expect(page.getByTestId('stats-surface')).not.toContainText('unavailable');
  await expect(page.getByTestId('stats-output')).toContainText(`${int(230 * 16 * 2)} tris`, { timeout: 5_000 });
  // A cube with a hole: its other 5 faces' patches, drawn.
  await dropFile(page, 'holed-cube.obj', HOLED_CUBE);
  await expect(page.getByTestId('stats-cage')).toContainText('holed-cube.obj', { timeout: 10_000 });
  await expect(page.getByTestId('stats-surface')).toContainText('Pm ACC', { timeout: 5_000 });
  await expect(page.getByTestId('stats-surface')).not.toContainText('unavailable');
  await expect(page.getByTestId('stats-output')).toContainText(`${int(5 * 16 * 2)} tris`, { timeout: 5_000 });
  expect(errors).toEqual([]);
});

test('flat shading (the instanced tessellator) changes the picture, and back', async ({ page }) => {
  const errors = collectErrors(page);
  // ui=0: no stats or panel over the canvas (masks sized by a stats panel that grows as its
  // timings arrive made the first picture differ from the last one).
  await page.goto('/?model=torus&tessellator=instanced&mode=fixed&level=4&wire=0&t=0&ui=0');
  await ready(page);
  const canvas = () => page.locator('#view').screenshot();
  const set = (flat: boolean) =>
    page.evaluate(
      (f) => (window as unknown as { tessellab: { demo: { setInstancedFlat(f: boolean): void } } }).tessellab.demo.setInstancedFlat(f),
      flat,
    );
  const before = await canvas();
  await set(true);
  await expect.poll(async () => Buffer.compare(await canvas(), before)).not.toBe(0);
  await set(false);
  await expect.poll(async () => Buffer.compare(await canvas(), before)).toBe(0);
  expect(errors).toEqual([]);
});

test('exact Catmull-Clark on both tessellators: the split view draws compute CC beside instanced CC, the same triangle count, no console errors', async ({
  page,
}) => {
  const errors = collectErrors(page);
  await page.goto('/?model=creature&surface=catmull-clark&split=1&instsurface=catmull-clark&mode=fixed&factor=8&level=8&t=0');
  await ready(page);
  await expect(page.getByTestId('stats-surface')).toContainText('instanced (right): Catmull-Clark', { timeout: 10_000 });
  // Matched settings: level 8 draws 128 triangles a quad and 64 a triangle patch, as factor 8.
  const tris = int(556 * 128 + 16 * 64);
  await expect(page.getByTestId('stats-output-compute')).toContainText(`${tris} tris`, { timeout: 10_000 });
  await expect(page.getByTestId('stats-output')).toContainText(`${tris} tris`, { timeout: 10_000 });
  const r = await records(page);
  expect(r!.gpu).toEqual(r!.cpu);
  const shot = PNG.sync.read(
    await page.locator('#view').screenshot({ mask: [page.locator('#stats'), page.locator('.lil-gui.panel')], maskColor: '#000000' }),
  );
  const halves = [0, 0];
  for (let y = 0; y < shot.height; y++)
    for (let x = 0; x < shot.width; x++) {
      const k = 4 * (y * shot.width + x);
      if (shot.data[k] + shot.data[k + 1] + shot.data[k + 2] > 400) halves[x < shot.width / 2 ? 0 : 1]++;
    }
  expect(halves[0]).toBeGreaterThan(500);
  expect(halves[1]).toBeGreaterThan(500);
  expect(errors).toEqual([]);
});

test('displacement: the brick box drawn displaced by the instanced tessellator (alone, Phong) and on both halves of the split view (exact Catmull-Clark); disp=0 changes each; no console errors', async ({
  page,
}) => {
  test.setTimeout(180_000);
  const errors = collectErrors(page);
  /** The canvas alone (ui=0: no panels), once two shots a moment apart agree. */
  const shot = async (query: string) => {
    await page.goto(`/?model=brick-box&t=0&ui=0&wire=0${query}`);
    await ready(page);
    let before = await page.locator('#view').screenshot();
    for (let i = 0; i < 40; i++) {
      await page.waitForTimeout(250);
      const again = await page.locator('#view').screenshot();
      if (Buffer.compare(again, before) === 0) break;
      before = again;
    }
    return PNG.sync.read(before);
  };
  /** Pixels that differ between two shots, in the left and the right half. */
  const differing = (a: PNG, b: PNG) => {
    const n = [0, 0];
    for (let y = 0; y < a.height; y++)
      for (let x = 0; x < a.width; x++) {
        const k = 4 * (y * a.width + x);
        if (a.data[k] !== b.data[k] || a.data[k + 1] !== b.data[k + 1] || a.data[k + 2] !== b.data[k + 2]) n[x < a.width / 2 ? 0 : 1]++;
      }
    return n;
  };
  const alone = '&tessellator=instanced&mode=fixed&level=16';
  const displaced = await shot(alone);
  const flat = await shot(`${alone}&disp=0`);
  expect(differing(displaced, flat)[0] + differing(displaced, flat)[1]).toBeGreaterThan(500);

  const split = '&surface=catmull-clark&instsurface=catmull-clark&split=1&mode=fixed&factor=16&level=16';
  const [left, right] = differing(await shot(split), await shot(`${split}&disp=0`));
  // Both halves move: compute CC on the left, instanced CC on the right, both displaced.
  expect(left).toBeGreaterThan(200);
  expect(right).toBeGreaterThan(200);
  expect(errors).toEqual([]);
});
