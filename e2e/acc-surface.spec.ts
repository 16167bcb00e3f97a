// The ACC schemes as the compute tessellator's surface in the demo (`?surface=bezier-acc` …):
// drawn with no console errors and named in the stats; a cage a scheme refuses (an n-gon) is
// drawn as Phong with the reason, and the picture differs from the exact surface's.
import { expect, test } from '@playwright/test';
import { collectErrors, ready } from './helpers.ts';

test('each ACC scheme draws the creature; the icosphere (a pentagon) falls back to Phong with the reason', async ({ page }) => {
  test.setTimeout(240_000);
  const errors = collectErrors(page);
  for (const [scheme, name] of [
    ['bezier-acc', 'Bezier ACC'],
    ['gregory-acc', 'Gregory ACC'],
    ['pm-acc', 'Pm ACC'],
  ]) {
    await page.goto(`/?model=creature&surface=${scheme}&mode=fixed&factor=4&t=0`);
    await ready(page);
    await expect(page.getByTestId('stats-surface')).toContainText(name, { timeout: 10_000 });
    await expect(page.getByTestId('stats-surface')).not.toContainText('unavailable');
  }
  await page.goto('/?model=icosphere&surface=pm-acc&mode=fixed&factor=4&t=0');
  await ready(page);
  await expect(page.getByTestId('stats-surface')).toContainText('Phong', { timeout: 10_000 });
  await expect(page.getByTestId('stats-surface')).toContainText('Pm ACC unavailable');
  await expect(page.getByText('5 corners').first()).toBeVisible();
  expect(errors).toEqual([]);
});

test('show irregular patches on an ACC surface: regular, irregular quads and triangles counted in the legend, the picture tinted', async ({
  page,
}) => {
  test.setTimeout(120_000);
  const errors = collectErrors(page);
  const shot = async (query: string) => {
    await page.goto(`/?model=creature&surface=gregory-acc&mode=fixed&factor=4&t=0${query}`);
    await ready(page);
    return page.locator('#view').screenshot({ mask: [page.locator('#stats'), page.locator('.lil-gui.panel'), page.getByTestId('legend')] });
  };
  const plain = await shot('');
  const tinted = await shot('&patches=1');
  const legend = page.getByTestId('legend');
  await expect(legend).toContainText('Gregory ACC');
  await expect(legend).toContainText('irregular quad');
  expect(Buffer.compare(plain, tinted)).not.toBe(0);
  expect(errors).toEqual([]);
});
