// The ACC schemes as the compute tessellator's surface in the demo (`?surface=bezier-acc` …):
// drawn with no console errors and named in the stats; a cage with n-gons is refined once first
// (src/subdiv/acc.ts accCage), which the stats say; a cage with a hole is drawn without it.
import { expect, test } from '@playwright/test';
import { HOLED_CUBE, collectErrors, dropFile, ready } from './helpers.ts';

test('each ACC scheme draws the creature; the icosphere (pentagons) is refined once and says so; a holed cube is drawn', async ({
  page,
}) => {
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
    await expect(page.getByTestId('stats-surface')).not.toContainText('Catmull-Clark step');
  }
  await page.goto('/?model=icosphere&surface=pm-acc&mode=fixed&factor=4&t=0');
  await ready(page);
  const surface = page.getByTestId('stats-surface');
  await expect(surface).toContainText('Pm ACC', { timeout: 10_000 });
  await expect(surface).not.toContainText('unavailable');
  await expect(surface).toContainText('one Catmull-Clark step first (the cage has n-gons): 230 patches');
  await expect(page.getByTestId('stats-output')).toContainText('tris');
  // Holes keep their patches (their points are the neighbours' ring) and are not drawn.
  await dropFile(page, 'holed-cube.obj', HOLED_CUBE);
  await expect(page.getByTestId('stats-cage')).toContainText('holed-cube.obj', { timeout: 10_000 });
  await expect(surface).toContainText('Pm ACC', { timeout: 10_000 });
  await expect(surface).not.toContainText('unavailable');
  await expect(surface).not.toContainText('Catmull-Clark step');
  // 5 faces of 4 × 4 × 2 triangles at factor 4 (the hole's face is not drawn).
  await expect(page.getByTestId('stats-output')).toContainText('160 tris', { timeout: 10_000 });
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
