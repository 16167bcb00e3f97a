// The first frame of the production build (`npm run build`, served as `npm run preview` serves it),
// reported, not held: navigation to the first lit pixel of the model (the flat cage drawn while the
// surface is prepared, or the surface itself) and to the first complete frame of the exact surface
// (the page's "ready"), cold (a new browser context: no HTTP or shader cache of an earlier page).
// On SwiftShader the wait is mostly the exact surface's shaders compiling on one CPU thread.
// The CI builds before its end-to-end tests; without a build (dist/index.html) this says so and skips.
import { existsSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import { PNG } from 'pngjs';
import { preview, type PreviewServer } from 'vite';

const dist = process.env.FIRST_FRAME_DIST ?? 'dist';
let server: PreviewServer | null = null;

test.beforeAll(async () => {
  if (!existsSync(`${dist}/index.html`)) return;
  server = await preview({ logLevel: 'silent', build: { outDir: dist }, preview: { port: 0, strictPort: false, open: false } });
});
test.afterAll(async () => {
  await server?.close();
});

test('the production build: navigation to the first lit pixel and to the first complete frame (reported)', async ({ browser }) => {
  test.skip(!server, `no production build in ${dist}/ (npm run build)`);
  test.setTimeout(120_000);
  const url = server!.resolvedUrls!.local[0];
  const context = await browser.newContext({ viewport: { width: 800, height: 600 } });
  const page = await context.newPage();
  const start = Date.now();
  await page.goto(`${url}?t=0&ui=0`);
  // A lit pixel: the clay is far brighter than the backdrop and the ground (luminance > 110 of 255).
  let lit = -1;
  while (Date.now() - start < 90_000) {
    const png = PNG.sync.read(await page.screenshot());
    let bright = 0;
    for (let i = 0; i < png.data.length; i += 4)
      if (0.2126 * png.data[i] + 0.7152 * png.data[i + 1] + 0.0722 * png.data[i + 2] > 110) bright++;
    if (bright > 50) {
      lit = Date.now() - start;
      break;
    }
    await page.waitForTimeout(50);
  }
  expect(lit).toBeGreaterThan(0);
  await expect(page.locator('body')).toHaveAttribute('data-state', 'ready', { timeout: 90_000 });
  const ready = Date.now() - start;
  test
    .info()
    .annotations.push(
      { type: 'first lit pixel (ms, production build, cold)', description: String(lit) },
      { type: 'first complete frame (ms, production build, cold)', description: String(ready) },
    );
  console.log(`production build: first lit pixel ${lit} ms, first complete frame ${ready} ms`);
  await context.close();
});
