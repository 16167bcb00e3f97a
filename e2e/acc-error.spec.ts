// The ACC error views in the demo (`?errorview=geometry|normal`, `?compare=`): the heat map draws
// with no console errors, the legend (colour bar and numbers) shows, the stats give max / RMS;
// the all-regular torus measures exactly 0; the comparison view draws a heat map on both halves,
// each labelled with its scheme and error. The heat colours are found in the screenshot by
// their saturation (the ramp's blue, green, red; the clay and the backdrop are greyish).
import { expect, type Page, test } from '@playwright/test';
import { PNG } from 'pngjs';
import { collectErrors, ready } from './helpers.ts';

/** Pixels of the page in columns [x0, x1) (fractions) whose colour is one of the ramp's: a
 * channel at least 70 above both others. */
async function heatPixels(page: Page, x0: number, x1: number): Promise<number> {
  const img = PNG.sync.read(await page.screenshot());
  let n = 0;
  const from = Math.round(x0 * img.width),
    to = Math.round(x1 * img.width);
  for (let y = 0; y < img.height; y++)
    for (let x = from; x < to; x++) {
      const i = 4 * (y * img.width + x);
      const [r, g, b] = [img.data[i], img.data[i + 1], img.data[i + 2]];
      if (b > r + 70 && b > g + 70) n++;
      else if (g > r + 70 && g > b + 70) n++;
      else if (r > g + 70 && r > b + 70) n++;
    }
  return n;
}

test('geometry and normal heat maps on the creature: legend, max / RMS, heat colours; the torus measures 0', async ({ page }) => {
  test.setTimeout(240_000);
  const errors = collectErrors(page);
  await page.goto('/?model=creature&surface=gregory-acc&mode=fixed&factor=4&t=0&wire=0&cap=0.5');
  await ready(page);
  const clay = await heatPixels(page, 0, 1);

  await page.goto('/?model=creature&surface=gregory-acc&mode=fixed&factor=4&t=0&wire=0&cap=0.5&errorview=geometry');
  await ready(page);
  const legend = page.getByTestId('legend');
  await expect(legend).toBeVisible();
  await expect(legend).toContainText('Geometry error');
  await expect(page.getByTestId('heat-bar')).toBeVisible();
  await expect(page.getByTestId('heat-ticks')).toContainText('0.250%');
  await expect(page.getByTestId('stats-error')).toContainText('RMS', { timeout: 90_000 }); // SwiftShader under load: the heat pipelines compile the exact evaluator
  const max = await page.getByTestId('err-max-geometry').textContent();
  expect(Number.parseFloat(max ?? '')).toBeGreaterThan(0);
  await expect(legend).toContainText('max');
  const heat = await heatPixels(page, 0, 1);
  expect(heat).toBeGreaterThan(2000);
  expect(clay).toBeLessThan(heat / 10);

  await page.goto('/?model=creature&surface=bezier-acc&mode=fixed&factor=4&t=0&wire=0&cap=0.5&errorview=normal&errrange=2');
  await ready(page);
  await expect(legend).toContainText('Normal error');
  await expect(page.getByTestId('heat-ticks')).toContainText('2.00°');
  await expect(page.getByTestId('stats-error')).toContainText('RMS', { timeout: 90_000 }); // SwiftShader under load: the heat pipelines compile the exact evaluator
  expect(Number.parseFloat((await page.getByTestId('err-max-normal').textContent()) ?? '')).toBeGreaterThan(0);

  await page.goto('/?model=torus&surface=pm-acc&mode=fixed&factor=4&t=0&cap=0.5&errorview=geometry');
  await ready(page);
  await expect(page.getByTestId('stats-error')).toContainText('RMS', { timeout: 90_000 }); // SwiftShader under load: the heat pipelines compile the exact evaluator
  await expect(page.getByTestId('err-max-geometry')).toHaveText('0%');
  await expect(page.getByTestId('err-max-normal')).toHaveText('0°');
  expect(errors).toEqual([]);
});

test('comparison view: two schemes side by side, each labelled with its error', async ({ page }) => {
  test.setTimeout(240_000);
  const errors = collectErrors(page);
  await page.goto('/?model=creature&surface=bezier-acc&compare=gregory-acc&errorview=geometry&mode=fixed&factor=4&t=0&wire=0&cap=0.5');
  await ready(page);
  await expect(page.getByTestId('compare-left')).toContainText('Bezier ACC · max', { timeout: 30_000 });
  await expect(page.getByTestId('compare-right')).toContainText('Gregory ACC · max', { timeout: 30_000 });
  await expect(page.getByTestId('stats-compare')).toContainText('Gregory ACC');
  await expect(page.getByTestId('stats-error-right')).toContainText('RMS');
  // The picture without the panels over it.
  await page.goto('/?model=creature&surface=bezier-acc&compare=gregory-acc&errorview=geometry&mode=fixed&factor=4&t=0&wire=0&cap=0.5&ui=0');
  await ready(page);
  expect(await heatPixels(page, 0, 0.5)).toBeGreaterThan(2000);
  expect(await heatPixels(page, 0.5, 1)).toBeGreaterThan(2000);
  expect(errors).toEqual([]);
});
