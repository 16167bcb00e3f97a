// The demo page (index.html) end to end, in headless Chromium on SwiftShader: it starts without
// console errors, draws a deterministic frozen frame, survives a bad OBJ and a lost device, and
// explains itself when WebGPU is missing.
import { expect, test, type Page } from '@playwright/test';

/** Console errors and uncaught exceptions of a page, collected from the start. */
function collectErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(e.message));
  return errors;
}

async function ready(page: Page): Promise<void> {
  await expect(page.locator('body')).toHaveAttribute('data-state', 'ready', { timeout: 45_000 });
}

/** Drop a file on the page the way a user's drag and drop does. */
async function dropFile(page: Page, name: string, text: string): Promise<void> {
  const dataTransfer = await page.evaluateHandle(({ name, text }) => {
    const dt = new DataTransfer();
    dt.items.add(new File([text], name, { type: 'text/plain' }));
    return dt;
  }, { name, text });
  await page.dispatchEvent('body', 'dragenter', { dataTransfer });
  await page.dispatchEvent('body', 'drop', { dataTransfer });
}

test('loads a model without console errors and shows its stats', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('/?model=torus&t=0');
  await ready(page);
  await expect(page.getByTestId('stats-cage')).toContainText('torus');
  await expect(page.getByTestId('stats-cage')).toContainText('128 verts');
  await expect(page.getByTestId('stats-output')).toContainText('tris');
  await expect(page.locator('#loading')).toBeHidden();
  await expect(page.locator('.lil-gui.panel')).toContainText('Tessellation');
  await expect(page.getByRole('link', { name: /diagrams/i })).toHaveAttribute('href', './diagrams/index.html');
  expect(errors).toEqual([]);
});

test.describe('frozen frames (?t=) match their references', () => {
  // A desktop-sized window: the panels leave the model room, as on a laptop.
  test.use({ viewport: { width: 1200, height: 750 } });

  test('the whole page, with the cage overlay', async ({ page }) => {
    const errors = collectErrors(page);
    await page.goto('/?model=pawn&t=0&cage=1');
    await ready(page);
    // The stats show live timings: mask them, keep everything else (panel, title, canvas).
    await expect(page).toHaveScreenshot('pawn-frozen.png', { mask: [page.locator('#stats')], maskColor: '#161a20' });
    expect(errors).toEqual([]);
  });

  test('the canvas alone, fixed factors', async ({ page }) => {
    await page.goto('/?model=creature&t=0&ui=0&mode=fixed&factor=6');
    await ready(page);
    await expect(page.locator('#view')).toHaveScreenshot('creature-fixed-6.png');
  });
});

/** The number of geometry builds so far, from the stats panel. */
async function builds(page: Page): Promise<number> {
  const text = (await page.getByTestId('stats-frame').textContent()) ?? '';
  return Number(/([\d,]+) builds?/.exec(text)?.[1].replace(/,/g, '') ?? NaN);
}

test('rebuilds the geometry only when the camera (adaptive), factors or model change', async ({ page }) => {
  await page.goto('/?model=torus&t=0');
  await ready(page);
  await expect.poll(() => builds(page)).toBe(1);
  // Overlays redraw the stored mesh: no rebuild.
  await page.locator('.lil-gui.panel').getByText('wireframe').click();
  await page.locator('.lil-gui.panel').getByText('cage overlay').click();
  await page.waitForTimeout(300);
  expect(await builds(page)).toBe(1);
  // Adaptive factors follow the camera: a drag rebuilds.
  const box = (await page.locator('#view').boundingBox())!;
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 60, box.y + box.height / 2 + 10, { steps: 3 });
  await page.mouse.up();
  await expect.poll(() => builds(page)).toBeGreaterThan(1);
  // Fixed factors do not depend on the camera: switching rebuilds once, turning the view does not.
  await page.goto('/?model=torus&t=0&mode=fixed&factor=3');
  await ready(page);
  await expect.poll(() => builds(page)).toBe(1);
  await page.locator('#view').focus();
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('+');
  await page.waitForTimeout(500);
  expect(await builds(page)).toBe(1);
});

test('the turntable rebuilds adaptive geometry every frame without errors', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('/?model=torus&spin=1');
  await ready(page);
  await expect.poll(() => builds(page), { timeout: 20_000 }).toBeGreaterThan(3);
  expect(errors).toEqual([]);
});

test('a bad OBJ shows its error with line numbers and keeps the model', async ({ page }) => {
  await page.goto('/?model=torus&t=0');
  await ready(page);
  const before = await page.locator('#view').screenshot();
  await dropFile(page, 'broken.obj', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n');
  const toast = page.getByTestId('toast-error');
  await expect(toast).toBeVisible();
  await expect(toast).toContainText('Could not load broken.obj');
  await expect(toast).toContainText('line 4');
  await expect(toast).toContainText('Still showing torus');
  await expect(page.getByTestId('stats-cage')).toContainText('torus');
  // The same frame as before (once the message, drawn over the canvas, is dismissed).
  await toast.getByRole('button', { name: 'Dismiss' }).click();
  await expect(toast).toBeHidden();
  expect(await page.locator('#view').screenshot()).toEqual(before);
  // A good file replaces the model.
  await dropFile(page, 'quad.obj', 'v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n');
  await expect(page.getByTestId('stats-cage')).toContainText('quad.obj');
});

test('a missing model falls back to the default with a message', async ({ page }) => {
  await page.goto('/?model=no-such-model&t=0');
  await ready(page);
  await expect(page.getByTestId('toast-error')).toContainText('no-such-model');
  await expect(page.getByTestId('stats-cage')).toContainText('creature');
});

test('?model= takes a URL', async ({ page }) => {
  await page.goto(`/?model=${encodeURIComponent('./models/gear.obj')}&t=0`);
  await ready(page);
  await expect(page.getByTestId('stats-cage')).toContainText('gear.obj');
});

test('recovers from a lost device', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('/?model=torus&t=0');
  await ready(page);
  await page.evaluate(() => (window as unknown as { tessellab: { loseDevice(): void } }).tessellab.loseDevice());
  await expect(page.getByRole('status').filter({ hasText: 'GPU device lost' })).toBeVisible();
  await ready(page);
  await expect(page.locator('dialog#fatal')).not.toBeVisible();
  await expect(page.getByTestId('stats-cage')).toContainText('torus');
  // Only the expected warning, no errors from using the dead device's resources.
  expect(errors).toEqual([]);
});

test('without WebGPU the page says so', async ({ page }) => {
  await page.addInitScript(() => {
    delete (Navigator.prototype as { gpu?: unknown }).gpu;
  });
  await page.goto('/');
  const dialog = page.locator('dialog#fatal');
  await expect(dialog).toBeVisible();
  await expect(dialog).toContainText('WebGPU is not available');
  await expect(dialog).toContainText('navigator.gpu');
  await expect(page.locator('body')).toHaveAttribute('data-state', 'no-webgpu');
  // The diagrams need no WebGPU: the message points there.
  await expect(dialog.getByRole('link', { name: /diagrams/i })).toHaveAttribute('href', './diagrams/index.html');
  await expect(page).toHaveScreenshot('no-webgpu.png');
});
