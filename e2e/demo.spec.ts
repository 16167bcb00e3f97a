// The demo page (index.html) end to end, in headless Chromium on SwiftShader: it starts without
// console errors on the Catmull-Clark surface, draws deterministic frozen frames (Catmull-Clark,
// patch colours, Phong), falls back to Phong where the Catmull-Clark preparation refuses a cage, survives a
// bad OBJ and a lost device, and explains itself when WebGPU is missing.
import { expect, test, type Page } from '@playwright/test';
import { PNG } from 'pngjs';
import { CUBE_LINES, collectErrors, dropFile, ready } from './helpers.ts';

/** What the panel's cage picker shows. */
function picked(page: Page) {
  return page.locator('.lil-gui.panel .lil-option').filter({ hasText: 'cage' }).first().locator('.lil-display');
}

test('loads a model without console errors and shows its stats', async ({ page }) => {
  const errors = collectErrors(page);
  const requests: string[] = [];
  page.on('request', (r) => requests.push(r.url()));
  const start = Date.now();
  await page.goto('/?model=torus&t=0');
  await ready(page);
  // Reported, not held (a software GPU under a test runner's load): navigation to the first
  // complete frame of the exact surface, which waits mostly for its shaders to compile.
  test.info().annotations.push({ type: 'first frame (ms, dev server)', description: String(Date.now() - start) });
  // The counts and the draw timings follow the first frame within moments, not at the next rebuild.
  await expect(page.getByTestId('stats-output')).toContainText('tris', { timeout: 3_000 });
  await expect(page.getByTestId('stats-gpu')).not.toHaveText('…', { timeout: 3_000 });
  await expect(page.getByTestId('stats-cage')).toContainText('torus');
  await expect(page.getByTestId('stats-cage')).toContainText('128 verts');
  await expect(picked(page)).toHaveText('Torus');
  // The model list is built in: no request for an index (the built site has none: a 404 in the console).
  expect(requests.filter((u) => u.includes('index.json'))).toEqual([]);
  // Catmull-Clark by default (topology prepared on the page's thread); the talk's numbers in the panel.
  await expect(page.getByTestId('stats-surface')).toContainText('Catmull-Clark');
  await expect(page.getByTestId('stats-surface')).toContainText('256 regular');
  await expect(page.getByTestId('stats-other')).toContainText(/fixed, factor 8/);
  await expect(page.getByTestId('stats-other')).toContainText('tris');
  if (
    await page.evaluate(
      () => (window as unknown as { tessellab: { demo: { gpu: { timestamps: boolean } } } }).tessellab.demo.gpu.timestamps,
    )
  ) {
    await expect(page.getByTestId('stats-subdiv')).toContainText('patch build');
    await expect(page.getByTestId('stats-build')).toContainText('tessellate');
  }
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
    await page.goto('/?model=pawn&t=0&cage=1&wire=1');
    await ready(page);
    // The stats show live timings: mask them, keep everything else (panel, title, canvas).
    await expect(page).toHaveScreenshot('pawn-frozen.png', { mask: [page.locator('#stats')], maskColor: '#161a20' });
    expect(errors).toEqual([]);
  });

  test('the canvas alone, Phong, fixed factors', async ({ page }) => {
    await page.goto('/?model=creature&t=0&ui=0&mode=fixed&factor=6&surface=phong&wire=1');
    await ready(page);
    await expect(page.locator('#view')).toHaveScreenshot('creature-fixed-6.png');
  });

  test('the canvas alone, Catmull-Clark (the default), adaptive', async ({ page }) => {
    const errors = collectErrors(page);
    await page.goto('/?model=creature&t=0&ui=0&wire=1');
    await ready(page);
    await expect(page.locator('#view')).toHaveScreenshot('creature-cc.png');
    expect(errors).toEqual([]);
  });

  test('Catmull-Clark with patch colours and the legend', async ({ page }) => {
    const errors = collectErrors(page);
    await page.goto('/?model=pawn&t=0&patches=1&wire=0');
    await ready(page);
    await expect(page.getByTestId('legend')).toContainText('irregular quad');
    // The stats show live timings: mask them.
    await expect(page.locator('#view')).toHaveScreenshot('pawn-cc-patches.png', { mask: [page.locator('#stats')], maskColor: '#161a20' });
    expect(errors).toEqual([]);
  });
});

/** The panel's control labelled `name`. */
function control(page: Page, name: string) {
  return page.locator('.lil-gui.panel .lil-controller').filter({ has: page.locator('.lil-name', { hasText: new RegExp(`^${name}$`) }) });
}

test('the patch-colour toggle changes the picture, and back', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('/?model=pawn&t=0');
  await ready(page);
  const legend = page.getByTestId('legend');
  await expect(legend).toBeHidden();
  // The canvas without the panels over it (timings change with every frame; the focus ring
  // moves). Hidden for the shot rather than masked: a mask is the stats' box at each shot, and
  // the box grows as its timings arrive, which under a loaded machine came after the reference
  // had been taken (the picture after the toggle then never matched it again).
  const canvas = () => page.locator('#view').screenshot({ style: '#stats, .lil-gui.panel { visibility: hidden !important; }' });
  // The reference is the first picture that the next one repeats.
  let before = await canvas();
  for (let i = 0; i < 40; i++) {
    await page.waitForTimeout(250);
    const again = await canvas();
    if (Buffer.compare(again, before) === 0) break;
    before = again;
  }
  await control(page, 'patch colours').locator('input').check();
  await expect(legend).toBeVisible();
  await expect(legend).toContainText('crease');
  await expect.poll(async () => Buffer.compare(await canvas(), before)).not.toBe(0);
  await control(page, 'patch colours').locator('input').uncheck();
  await expect(legend).toBeHidden();
  await expect.poll(async () => Buffer.compare(await canvas(), before)).toBe(0);
  expect(errors).toEqual([]);
});

test('the surface switch: Phong, flat cage and back to Catmull-Clark; a model picked again is not fetched or prepared again', async ({
  page,
}) => {
  const errors = collectErrors(page);
  const fetched: string[] = [];
  page.on('request', (r) => fetched.push(new URL(r.url()).pathname));
  await page.goto('/?model=torus&t=0&up=z');
  await ready(page);
  const modelUp = () => page.evaluate(() => (window as unknown as { tessellab: { modelUp(): number[] } }).tessellab.modelUp());
  expect(await modelUp()).toEqual([0, 0, -1]);
  // Away and back: the same cage (its surface data cached with it), not a second download.
  const cage = page.locator('.lil-gui.panel .lil-option').filter({ hasText: 'cage' }).first().locator('select');
  await cage.selectOption({ label: 'Gear' });
  await expect(page.getByTestId('stats-cage')).toContainText('gear');
  // The link's up axis was the torus's: the gear opens Y-up, as it is stored.
  expect(await modelUp()).toEqual([0, 1, 0]);
  await cage.selectOption({ label: 'Torus' });
  await expect(page.getByTestId('stats-cage')).toContainText('torus');
  expect(fetched.filter((p) => p.endsWith('/torus.obj'))).toHaveLength(1);
  const surface = control(page, 'surface').locator('select');
  await surface.selectOption({ label: 'Phong' });
  await expect(page.getByTestId('stats-surface')).toHaveText('Phong');
  await expect(control(page, 'flat baseline')).toBeHidden();
  await expect(page).toHaveURL(/surface=phong/);
  await surface.selectOption({ label: 'flat cage' });
  await expect(page.getByTestId('stats-output')).toContainText('cage (flat)');
  await surface.selectOption({ label: 'Catmull-Clark' });
  await expect(page.getByTestId('stats-surface')).toContainText('Catmull-Clark');
  await expect(control(page, 'flat baseline')).toBeVisible();
  await control(page, 'flat baseline').locator('input').uncheck();
  await expect(page).toHaveURL(/flat=0/);
  await expect(page.getByTestId('stats-output')).toContainText('tris');
  expect(errors).toEqual([]);
});

test('a cage the Catmull-Clark preparation refuses falls back to Phong with a message', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('/?model=torus&t=0');
  await ready(page);
  // A semi-sharp crease of sharpness 8 under Chaikin's rule (which the fans do not take: the
  // halves of an edge decay differently) needs 8 uniform levels: refused by the GPU path's
  // preparation (src/gpu/cc/levels.ts MAX_LEVEL).
  const cube = [...CUBE_LINES, 't crease 2/1/0 4 5 8', 't creasemethod 0/0/1 chaikin'].join('\n');
  await dropFile(page, 'sharp-cube.obj', `${cube}\n`);
  const toast = page.getByRole('status').filter({ hasText: 'No Catmull-Clark surface for sharp-cube.obj' });
  await expect(toast).toContainText('needs more than 6 levels of refinement');
  await expect(toast).toContainText('Showing the Phong surface instead');
  await expect(page.getByTestId('stats-cage')).toContainText('sharp-cube.obj');
  await expect(page.getByTestId('stats-surface')).toContainText('Phong');
  await expect(page.getByTestId('stats-surface')).toContainText(
    'Catmull-Clark unavailable: Catmull-Clark: a face needs more than 6 levels',
  );
  await expect(page.getByTestId('stats-output')).toContainText('tris');
  expect(errors).toEqual([]);
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
  // The drag's builds land while earlier ones' timings are read back: once the page is still,
  // every figure is the newest build's, none left marked as an older one's.
  await expect(page.getByTestId('stats-build')).toBeVisible();
  await expect(page.getByTestId('stats-building')).toHaveCount(0, { timeout: 30_000 });
  await expect(page.getByTestId('stats-build-stale')).toHaveCount(0, { timeout: 30_000 });
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

test('a bad OBJ shows its error with line numbers and keeps the model; a good one replaces it, and no link claims it', async ({ page }) => {
  await page.goto('/?model=torus&t=0');
  await ready(page);
  // The canvas, not the panels over it: the stats fill in their timings as they come back, and a
  // screenshot taken before they had settled differed from the later one (a race, seen with two
  // test workers). Masking them was not enough: a mask is the box's size at that moment, and the
  // stats grow as their lines arrive (a CI run's first attempt: the two masks 160 and 178 px
  // wide). So they are hidden for the screenshot (visibility only: the layout and the frame stay).
  const canvas = async () => {
    const hide = await page.addStyleTag({ content: '#stats, .lil-gui.panel { visibility: hidden !important; }' });
    const png = await page.locator('#view').screenshot();
    await hide.evaluate((e) => (e as Element).remove());
    return png;
  };
  const before = await canvas();
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
  expect(await canvas()).toEqual(before);
  // A good file replaces the model.
  await dropFile(page, 'quad.obj', 'v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n');
  await expect(page.getByTestId('stats-cage')).toContainText('quad.obj');
  // The picker names the file, not the project model shown before it.
  await expect(picked(page)).toHaveText('quad.obj');
  // Nor does the address, and no link claims to show the file: a link cannot carry it.
  expect(new URL(page.url()).searchParams.get('model')).toBeNull();
  await page.getByText('copy link to this view').click();
  await expect(page.getByRole('status').filter({ hasText: 'No link to a local file' })).toContainText(
    'quad.obj is a file on this computer',
  );
});

test('on a wide window an error message covers neither the stats nor the panel; on a narrow one it lies above them', async ({ page }) => {
  const overlap = (a: { x: number; y: number; width: number; height: number } | null, b: typeof a) =>
    !!a && !!b && a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
  await page.setViewportSize({ width: 1280, height: 800 });
  await page.goto('/?model=torus&t=0');
  await ready(page);
  await page.getByTestId('stats-toggle').click(); // the stats at their widest
  await dropFile(page, 'broken.obj', 'f 1 2 3\n');
  const toast = page.getByTestId('toast-error');
  await expect(toast).toBeVisible();
  const box = await toast.boundingBox();
  expect(overlap(box, await page.locator('#stats').boundingBox())).toBe(false);
  expect(overlap(box, await page.locator('.lil-gui.panel').boundingBox())).toBe(false);
  // Narrow: over whatever it covers, and its button answers.
  await page.setViewportSize({ width: 800, height: 600 });
  await toast.getByRole('button', { name: 'Dismiss' }).click({ timeout: 5_000 });
  await expect(toast).toBeHidden();
});

test('the model is framed in the canvas the open panel leaves free, and centred once the panel closes', async ({ page }) => {
  await page.setViewportSize({ width: 1000, height: 700 });
  await page.goto('/?model=creature&t=0');
  await ready(page);
  const panel = (await page.locator('.lil-gui.panel').boundingBox())!;
  // The model's pixels: brighter than the backdrop and the ground. The panel is hidden from the
  // screenshot (visibility only: it still takes its room, and the frame is not redrawn).
  const extent = async () => {
    const hide = await page.addStyleTag({ content: '.lil-gui.panel, .hud, .title { visibility: hidden !important; }' });
    const png = PNG.sync.read(await page.locator('#view').screenshot());
    await hide.evaluate((e) => (e as Element).remove());
    let x0 = png.width,
      x1 = -1;
    for (let y = 0; y < png.height; y++)
      for (let x = 0; x < png.width; x++) {
        const i = (y * png.width + x) * 4;
        if (0.2126 * png.data[i] + 0.7152 * png.data[i + 1] + 0.0722 * png.data[i + 2] > 110) {
          x0 = Math.min(x0, x);
          x1 = Math.max(x1, x);
        }
      }
    return { x0, x1 };
  };
  const open = await extent();
  expect(open.x1).toBeGreaterThan(open.x0);
  expect(open.x1).toBeLessThan(panel.x);
  // Closed, the panel takes no room: the picture slides right by half the room it took.
  await page.locator('.lil-gui.panel > .lil-title').click();
  await expect
    .poll(async () => {
      const closed = await extent();
      return closed.x0 + closed.x1 - (open.x0 + open.x1);
    })
    .toBeCloseTo(1000 - panel.x, -1);
});

test('a missing model falls back to the default with a message', async ({ page }) => {
  await page.goto('/?model=no-such-model&t=0');
  await ready(page);
  await expect(page.getByTestId('toast-error')).toContainText('no-such-model');
  await expect(page.getByTestId('stats-cage')).toContainText('creature');
  await expect(picked(page)).toHaveText('Creature');
});

test('?model= takes a URL', async ({ page }) => {
  await page.goto(`/?model=${encodeURIComponent('./models/gear.obj')}&t=0`);
  await ready(page);
  await expect(page.getByTestId('stats-cage')).toContainText('gear.obj');
  await expect(picked(page)).toHaveText('gear.obj');
});

test('hostile input: an outside ?model= link is not fetched; an opened cube beyond 32-bit floats is refused', async ({ page }) => {
  // One page load for both (each load waits for the creature's first frame on SwiftShader).
  test.setTimeout(120_000);
  const outside = 'http://example.com/x.obj';
  const requests: string[] = [];
  page.on('request', (r) => requests.push(r.url()));
  await page.goto(`/?model=${encodeURIComponent(outside)}&cap=1e9&t=0`);
  // The note is shown before the first model loads and goes after 10 s: checked first.
  await expect(page.getByRole('status').filter({ hasText: 'Link parameters adjusted' })).toContainText('cap=1e9 is outside');
  const refusal = page.getByTestId('toast-error');
  await expect(refusal).toContainText('Model link not loaded');
  await expect(refusal).toContainText('another site (http://example.com)');
  await ready(page);
  await expect(page.getByTestId('stats-cage')).toContainText('creature');
  expect(requests.filter((u) => new URL(u).hostname === 'example.com')).toEqual([]);

  // The panel's "open an OBJ file…" (its file input), with a cube at 1e39: the loader's line, the model kept.
  const huge =
    'v -1e39 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n' +
    'f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n';
  const chooser = page.waitForEvent('filechooser');
  await page.getByText('open an OBJ file…').click();
  await (await chooser).setFiles({ name: 'huge.obj', mimeType: 'text/plain', buffer: Buffer.from(huge) });
  await expect(refusal).toContainText('Could not load huge.obj');
  await expect(refusal).toContainText('line 1: vertex 1: coordinate -1e+39 is beyond');
  await expect(refusal).toContainText('Still showing creature');
  await expect(page.getByTestId('stats-cage')).toContainText('creature');
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

test.describe('on a phone (390 x 844)', () => {
  test.use({ viewport: { width: 390, height: 844 } });
  test('the panels cover at most a fifth of the canvas; the stats are compact until asked for all', async ({ page }) => {
    await page.goto('/?model=torus&t=0');
    await ready(page);
    await expect(page.getByTestId('stats-output')).toContainText('tris');
    // The area of the canvas under any panel (the title, the stats, the controls), each pixel once.
    const covered = () =>
      page.evaluate(() => {
        const view = (document.getElementById('view') as HTMLElement).getBoundingClientRect();
        const panels = ['.title', '#stats', '.lil-gui.panel', '.legend']
          .flatMap((s) => [...document.querySelectorAll(s)])
          .map((e) => e.getBoundingClientRect())
          .filter((r) => r.width > 0 && r.height > 0);
        let under = 0;
        for (let y = Math.floor(view.top); y < view.bottom; y += 2)
          for (let x = Math.floor(view.left); x < view.right; x += 2)
            if (panels.some((r) => x >= r.left && x < r.right && y >= r.top && y < r.bottom)) under += 4;
        return under / (view.width * view.height);
      });
    const compact = await covered();
    test.info().annotations.push({ type: 'canvas under panels (compact stats)', description: compact.toFixed(3) });
    expect(compact).toBeLessThanOrEqual(0.2);
    // Four rows and the button; every row is there for the asking.
    await expect(page.getByTestId('stats-memory')).toBeHidden();
    await page.getByTestId('stats-toggle').click();
    await expect(page.getByTestId('stats-memory')).toBeVisible();
    await page.getByTestId('stats-toggle').click();
    await expect(page.getByTestId('stats-memory')).toBeHidden();
  });
});
