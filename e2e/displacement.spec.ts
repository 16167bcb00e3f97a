// Displacement in the demo: the project's displaced models draw displaced (and differently with
// `disp=0` and in the UV-seam view) with no console errors; a dropped PNG height map changes the
// picture; a file that is not a PNG, or a map for a model without uvs, gives a clear message
// and keeps the map shown before.
import { expect, test, type Page } from '@playwright/test';
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
