// Helpers shared by the demo's end-to-end specs.
import { expect, type Page } from '@playwright/test';

/** Console errors and uncaught exceptions of a page, collected from the start. */
export function collectErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(e.message));
  return errors;
}

/** The page has drawn its first complete frame of the current model. A correctness check, not a
 * speed one: on SwiftShader a page's first frame waits for its pipelines to compile on one CPU
 * thread, and with two test workers on two cores (playwright.config.ts) a view that compiles the
 * exact evaluator twice (the error views) took over 45 s at the start of a run. */
export async function ready(page: Page): Promise<void> {
  await expect(page.locator('body')).toHaveAttribute('data-state', 'ready', { timeout: 90_000 });
}

/** Drop a file on the page the way a user's drag and drop does. */
export async function dropFile(page: Page, name: string, text: string): Promise<void> {
  const dataTransfer = await page.evaluateHandle(
    ({ name, text }) => {
      const dt = new DataTransfer();
      dt.items.add(new File([text], name, { type: 'text/plain' }));
      return dt;
    },
    { name, text },
  );
  await page.dispatchEvent('body', 'dragenter', { dataTransfer });
  await page.dispatchEvent('body', 'drop', { dataTransfer });
}

/** A cube's OBJ lines (8 vertices, 6 outward quads), for the specs that drop a tagged cube. */
export const CUBE_LINES = [
  'v -1 -1 -1',
  'v 1 -1 -1',
  'v 1 1 -1',
  'v -1 1 -1',
  'v -1 -1 1',
  'v 1 -1 1',
  'v 1 1 1',
  'v -1 1 1',
  'f 5 6 7 8',
  'f 1 4 3 2',
  'f 1 2 6 5',
  'f 2 3 7 6',
  'f 3 4 8 7',
  'f 4 1 5 8',
];

/** A cube with one face tagged as a hole (5 faces drawn). */
export const HOLED_CUBE = [...CUBE_LINES, 't hole 1/0/0 0', ''].join('\n');
