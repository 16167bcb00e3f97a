// The demo page under a long, mixed session (issue 13's soak): 200 camera moves (drags and wheel),
// 20 model switches (project models, dropped files: a malformed one, one whose name is HTML),
// 3 device losses, a hidden and shown tab and window resizes. Throughout: no console error, no
// dialog (an injected `alert` would open one), bad input keeps the previous model, the HTML file
// name is shown as text. At the end the page shows the first model again with the same settings
// in the same window, and the GPU memory it holds (the bytes of its live buffers and textures,
// counted by src/gpu/device/tracked-device.ts) is exactly what it held after that model's first load:
// every buffer or texture made along the way was destroyed (or died with its lost device).
//
// Kept short on SwiftShader: small models, fixed factor 2, small output buffers (cap=0.05, i.e.
// 50,000 vertices), one frame per camera move.
import { expect, test, type Page } from '@playwright/test';
import { dropFile, ready } from './helpers.ts';

interface Memory {
  bytes: number;
  buffers: number;
  textures: number;
  byLabel: Record<string, number>;
}

const HTML_NAME = '<img src=x onerror=alert(1)>.obj';
const QUAD = 'v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n';
/** A cube with one face that names a vertex that does not exist (line 10). */
const MALFORMED = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf 1 2 3 4\nf 5 6 7 99\n';
const SMALL_MODELS = [
  { name: 'pawn', label: 'Chess pawn' },
  { name: 'creased-box', label: 'Creased box' },
  { name: 'gear', label: 'Gear' },
  { name: 'icosphere', label: 'Icosphere ball' },
  { name: 'sheet', label: 'Open sheet' },
  { name: 'torus', label: 'Torus' },
];

function gpuMemory(page: Page): Promise<Memory> {
  return page.evaluate(() => (window as unknown as { tessellab: { gpuMemory(): Memory } }).tessellab.gpuMemory());
}

/** What the panel's cage picker shows. */
function picked(page: Page) {
  return page.locator('.lil-gui.panel .lil-option').filter({ hasText: 'cage' }).first().locator('.lil-display');
}

function pickerSelect(page: Page) {
  return page.locator('.lil-gui.panel .lil-option').filter({ hasText: 'cage' }).first().locator('select');
}

/** `title` is shown, tessellated (its counts read back). */
async function shownModel(page: Page, title: string): Promise<void> {
  await expect(page.getByTestId('stats-cage')).toContainText(title, { timeout: 30_000 });
  await expect(page.getByTestId('stats-output')).toContainText('tris', { timeout: 30_000 });
}

/** `n` camera moves: drags (one frame each) and, every fourth move, a wheel step (in, then out). */
async function moveCamera(page: Page, n: number, seed: number): Promise<void> {
  const box = (await page.locator('#view').boundingBox())!;
  // Away from the panels: the left half, below the title.
  const x0 = box.x + box.width * 0.3,
    y0 = box.y + box.height * 0.6;
  for (let i = 0; i < n; i++) {
    const k = seed + i;
    if (k % 4 === 3) {
      await page.mouse.move(x0, y0);
      await page.mouse.wheel(0, k % 8 === 3 ? -120 : 120);
    } else {
      await page.mouse.move(x0, y0);
      await page.mouse.down();
      await page.mouse.move(x0 + ((k * 37) % 61) - 30, y0 + ((k * 17) % 31) - 15, { steps: 1 });
      await page.mouse.up();
    }
  }
}

type LossHooks = { tessellab: { loseDevice(): void; demo: { gpu: { device: object } } }; lostDevice?: object };

async function loseDevice(page: Page, title: string): Promise<void> {
  await page.evaluate(() => {
    const w = window as unknown as LossHooks;
    w.lostDevice = w.tessellab.demo.gpu.device;
    w.tessellab.loseDevice();
  });
  // The page is recovered when it holds a new device. Not by watching data-state leave 'ready':
  // the 'lost' state lasts only as long as the recovery, which can end between two polls (this
  // check passed only on retry in CI).
  await expect
    .poll(() =>
      page.evaluate(() => (window as unknown as LossHooks).tessellab.demo.gpu.device !== (window as unknown as LossHooks).lostDevice),
    )
    .toBe(true);
  await ready(page);
  await shownModel(page, title);
}

/** Hide the tab and show it again, as the browser does when the user switches tabs. */
async function setHidden(page: Page, hidden: boolean): Promise<void> {
  await page.evaluate((hidden) => {
    if (hidden) {
      Object.defineProperty(document, 'visibilityState', { configurable: true, get: () => 'hidden' });
      Object.defineProperty(document, 'hidden', { configurable: true, get: () => true });
    } else {
      // The own properties shadow Document.prototype's getters: removing them restores the truth.
      delete (document as { visibilityState?: unknown }).visibilityState;
      delete (document as { hidden?: unknown }).hidden;
    }
    document.dispatchEvent(new Event('visibilitychange'));
  }, hidden);
}

// A small window (every camera move draws a frame, and SwiftShader's cost is per pixel), wide
// enough that the panel starts open (it starts closed at 640 px and below).
test.use({ viewport: { width: 660, height: 400 }, actionTimeout: 30_000 });

test('soak: camera moves, model switches, bad files, device losses, a hidden tab and resizes', async ({ page }) => {
  test.setTimeout(240_000);
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(e.message));
  const dialogs: string[] = [];
  page.on('dialog', (d) => {
    dialogs.push(`${d.type()}: ${d.message()}`);
    void d.dismiss();
  });
  const viewport = page.viewportSize()!;

  await page.goto('/?model=torus&mode=fixed&factor=2&cap=0.05');
  await ready(page);
  await shownModel(page, 'torus');
  const first = await gpuMemory(page);
  expect(first.bytes).toBeGreaterThan(0);
  await expect(page.getByTestId('stats-memory')).toContainText('MiB');

  let switches = 0;
  let moves = 0;
  const move = async (n: number) => {
    await moveCamera(page, n, moves);
    moves += n;
  };
  const pick = async (m: { name: string; label: string }) => {
    await pickerSelect(page).selectOption({ label: m.label });
    await shownModel(page, m.name);
    await expect(picked(page)).toHaveText(m.label);
    switches++;
  };

  // Project models, with camera moves between them.
  for (const m of SMALL_MODELS.slice(0, 4)) {
    await pick(m);
    await move(12);
  }

  // A malformed file: an error with its line, and the previous model stays.
  await dropFile(page, 'broken.obj', MALFORMED);
  const toast = page.getByTestId('toast-error');
  await expect(toast).toContainText('Could not load broken.obj');
  await expect(toast).toContainText('line 10');
  await expect(toast).toContainText('Still showing icosphere');
  await expect(page.getByTestId('stats-cage')).toContainText('icosphere');
  await expect(picked(page)).toHaveText('Icosphere ball');
  switches++;
  await move(12);

  // A malformed file whose name is HTML: shown as text in the message, never as markup.
  await dropFile(page, HTML_NAME, MALFORMED);
  await expect(toast).toContainText(`Could not load ${HTML_NAME}`);
  await expect(page.getByTestId('stats-cage')).toContainText('icosphere');
  await expect(page.locator('img')).toHaveCount(0);
  switches++;

  // A good file with that name: the stats and the picker show the name as text.
  await dropFile(page, HTML_NAME, QUAD);
  await expect(page.getByTestId('stats-cage')).toContainText(HTML_NAME, { timeout: 30_000 });
  await expect(picked(page)).toHaveText(HTML_NAME);
  await expect(page.locator('img')).toHaveCount(0);
  switches++;
  await move(12);

  // The first device loss, while a file is shown.
  await loseDevice(page, HTML_NAME);
  await move(12);

  // A hidden tab: camera input meanwhile, then shown again; the page draws and carries on.
  await setHidden(page, true);
  await move(4);
  await setHidden(page, false);
  await move(8);

  // Switches in quick succession: only the last one is shown.
  await pickerSelect(page).selectOption({ label: 'Gear' });
  await pickerSelect(page).selectOption({ label: 'Creased box' });
  switches += 2;
  await shownModel(page, 'creased-box');
  await expect(picked(page)).toHaveText('Creased box');

  // Window resizes (and camera moves at each size).
  for (const size of [
    { width: 640, height: 400 },
    { width: 320, height: 480 },
    { width: 560, height: 300 },
  ]) {
    await page.setViewportSize(size);
    await move(10);
  }
  await page.setViewportSize(viewport);

  // A device loss right after a switch was asked for (the load and the recovery overlap).
  await pickerSelect(page).selectOption({ label: 'Open sheet' });
  switches++;
  await loseDevice(page, 'sheet');
  await move(12);

  // More switches, files and moves; the third device loss.
  await dropFile(page, 'quad.obj', QUAD);
  await shownModel(page, 'quad.obj');
  switches++;
  await pick(SMALL_MODELS[2]);
  await move(12);
  await loseDevice(page, 'gear');
  for (const i of [0, 3, 1, 4, 0, 2, 3]) {
    await pick(SMALL_MODELS[i]);
    await move(6);
  }
  await move(Math.max(0, 200 - moves - 8));

  // Back to the first model, same settings, same window.
  await pick(SMALL_MODELS[5]);
  expect(switches).toBeGreaterThanOrEqual(20);
  await move(8);
  expect(moves).toBe(200);
  await page.waitForTimeout(300);
  const last = await gpuMemory(page);
  // Exact: the same model and settings hold the same buffers and textures. On a mismatch, the
  // labels whose bytes differ say what leaked (or what is missing).
  const diff = Object.fromEntries(
    [...new Set([...Object.keys(first.byLabel), ...Object.keys(last.byLabel)])]
      .filter((k) => first.byLabel[k] !== last.byLabel[k])
      .map((k) => [k, `${first.byLabel[k] ?? 0} → ${last.byLabel[k] ?? 0}`]),
  );
  expect(diff).toEqual({});
  expect({ bytes: last.bytes, buffers: last.buffers, textures: last.textures }).toEqual({
    bytes: first.bytes,
    buffers: first.buffers,
    textures: first.textures,
  });

  expect(dialogs).toEqual([]);
  expect(errors).toEqual([]);
});
