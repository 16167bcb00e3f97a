// The talk's four models (third-party cages in ../shared/cages, never copied into the project),
// each dropped on the demo as a file: the page prepares its Catmull-Clark data and draws the
// exact limit surface. Skipped, with the reason, where ../shared is absent (a fresh clone); CI has it.
import { existsSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { expect, test } from '@playwright/test';
import { collectErrors, dropFile, ready } from './helpers.ts';

const CAGES = resolve(import.meta.dirname, '../../shared/cages');

for (const name of ['suzanne', 'bigguy', 'monsterfrog', 'imrod']) {
  test(`${name}, dropped as a file, shows its Catmull-Clark surface`, async ({ page }) => {
    const file = resolve(CAGES, `${name}.obj`);
    test.skip(!existsSync(file), `${file} is not here (the talk's cages live in ../shared/cages)`);
    test.setTimeout(120_000);
    const errors = collectErrors(page);
    await page.goto('/?model=torus&t=0&mode=fixed&factor=2');
    await ready(page);
    await dropFile(page, `${name}.obj`, readFileSync(file, 'utf8'));
    await expect(page.getByTestId('stats-cage')).toContainText(`${name}.obj`, { timeout: 60_000 });
    const surface = page.getByTestId('stats-surface');
    await expect(surface).toContainText('Catmull-Clark', { timeout: 60_000 });
    await expect(surface).not.toContainText('unavailable');
    await expect(surface).toContainText('prepared in');
    await expect(page.getByTestId('stats-output')).toContainText('tris', { timeout: 60_000 });
    await expect(page.locator('#loading')).toBeHidden();
    // Upright: the four are stored Y-up, OBJ's convention, which a dropped file is read in (the
    // orbit camera's up is the world's +Y), and the URL names no model it does not show.
    expect(await page.evaluate(() => (window as unknown as { tessellab: { modelUp(): number[] } }).tessellab.modelUp())).toEqual([0, 1, 0]);
    await expect(page.getByTestId('stats-cage')).toContainText(`${name}.obj`);
    expect(new URL(page.url()).searchParams.get('model')).toBeNull();
    expect(errors).toEqual([]);
  });
}
