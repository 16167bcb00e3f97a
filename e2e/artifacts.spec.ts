// Issue 13: no pixel artifacts. The demo's frozen frame (?t=0&ui=0) of two project models, in
// adaptive and in fixed mode, against the same view tessellated at a high fixed factor: no
// isolated dark speckles, the dotted lines that folded slivers and back faces fighting front
// faces drew.
//
// A SPECKLE is a pixel of the frame whose luminance is below that of every pixel of the
// reference's 3×3 neighbourhood around it (itself and its 8 neighbours) by more than
// SPECKLE_THRESHOLD, and below the median of its own 8 neighbours in the frame by as much: darker
// than anything the reference has there, so not a silhouette moved by a pixel (the reference's
// neighbourhood then holds both sides), and a dot, not a region (a shadow edge or shading that
// differs over an area). A dotted line counts: each of its pixels has two dark neighbours of
// eight. The screenshots' PNG bytes are decoded by pngjs.
//
// SPECKLE_DUMP=DIR writes each case's frame, reference, and the frame with its speckles ringed.
//
// The reference is factor 16, not 32: on SwiftShader on a shared two-core machine the demo takes
// over two minutes to draw the creature at 32 (1.15 M triangles) and the test timed out.
//
// The cases: the project's creature and pawn, Phong and Catmull-Clark, adaptive and fixed; and
// suzanne, the cage of ../shared/evidence's pictures (third-party, in ../shared/cages, never
// copied into the project: served to the page from there by a route, and skipped where
// ../shared is absent, as in a fresh clone; CI has it).
//
// What took the speckles away (measured on this machine with this test's metric, before → after):
// - closed cages cull their back faces (earlier: creature adaptive Phong 135 → 8, pawn 157 → 1);
// - the gap strip's cut without caps (tests/gpu/tess/no-folds.test.ts; creature 8 → 1);
// - the lit pass interpolates position and normal at the centroid of a pixel's covered samples
//   (wgsl/render/lit.wgsl VertexOut): at the pixel's centre a contour pixel's position lay off its
//   triangle, under the surface, and the shadow lookup shaded it dark: the dotted lines along
//   suzanne's brow (fixed 8: 4 → 0) and most of the adaptive ones;
// - open cages drop the back faces whose surface normal faces the eye (the tessellation folding
//   over at a contour; wgsl/render/common.wgsl insideWeight) instead of lighting them as an inside,
//   and a shading normal that turns away from the eye is brought to the view plane (towardsEye).
// - an open cage's back faces are drawn in a second draw, depth-biased behind its front faces
//   (src/gpu/render/renderer.ts): the contour's two sheets no longer fight (suzanne adaptive Phong
//   22 → 18, and the factor-16 reference loses its own dotted brow: 4 and 3 dots → 0, which the
//   test now checks for every reference).
// - the factor rule counts twice the part of an edge's Phong offset that lies across the line
//   of sight where both ends face the eye (src/gpu/tess/factors.ts): silhouettes and occlusion
//   contours closer to the limit's (suzanne adaptive Catmull-Clark 32 → 26, Phong 18 → 17, pawn
//   adaptive Catmull-Clark 6 → 4, Phong 7 → 4; the creature's Catmull-Clark 5 → 6: one corner of
//   its outline, (396, 313), now lies a pixel further along and reads as two pixels).
// - the factor rule's bulge term (src/gpu/tess/factors.ts, wgsl/tess/factor-bulge.wgsl: the surface sampled
//   inside every cage triangle on screen): the adaptive outline within a pixel of the limit's
//   instead of 2–5 px (tests/gpu/tess/limit-distance.node.test.ts), which is what the remaining speckles
//   were: suzanne adaptive Catmull-Clark 26 → 0, adaptive Phong 17 → 1, pawn adaptive
//   Catmull-Clark 4 → 0, Phong 4 → 0, creature adaptive Catmull-Clark 6 → 0.
// - the Phong surface's α per edge, lowered where a corner's vertex normal lies near its face's
//   plane (src/gpu/surface/phong.ts; tests/gpu/tess/no-folds.test.ts), and the lit pass's shadow lookup offset
//   along the shading normal instead of the facet (wgsl/render/lit.wgsl shade: the facets of a
//   fine tessellation drew a grainy band where the pawn's head shadows its collar, in the
//   reference too): suzanne adaptive Phong 1 → 0 (the last, on the ear: the α did it), pawn
//   adaptive Phong stays 0 (1 with the α alone, in that band).
// Together: suzanne adaptive Catmull-Clark 58 → 0, adaptive Phong 81 → 0, creature adaptive
// Phong 135 → 0, pawn adaptive Phong 157 → 0.
import { expect, test, type Page } from '@playwright/test';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { PNG } from 'pngjs';

/** Luminance (0..1) difference a speckle must exceed. */
const SPECKLE_THRESHOLD = 0.1;

interface Image {
  width: number;
  height: number;
  rgba: Uint8Array;
}

/** A screenshot's pixels, RGBA (pngjs). */
function decodePng(png: Buffer): Image {
  const { width, height, data } = PNG.sync.read(png);
  return { width, height, rgba: new Uint8Array(data) };
}

function luminance(img: Image, x: number, y: number): number {
  const i = 4 * (y * img.width + x);
  return (0.2126 * img.rgba[i] + 0.7152 * img.rgba[i + 1] + 0.0722 * img.rgba[i + 2]) / 255;
}

/** The frame's isolated dark speckles against the reference (see the header), with a few positions. */
function speckles(frame: Image, ref: Image): { count: number; at: string[]; where: [number, number][] } {
  expect([frame.width, frame.height]).toEqual([ref.width, ref.height]);
  let count = 0;
  const at: string[] = [];
  const where: [number, number][] = [];
  for (let y = 1; y + 1 < frame.height; y++) {
    for (let x = 1; x + 1 < frame.width; x++) {
      let darkest = Infinity;
      for (let dy = -1; dy <= 1; dy++) for (let dx = -1; dx <= 1; dx++) darkest = Math.min(darkest, luminance(ref, x + dx, y + dy));
      const l = luminance(frame, x, y);
      if (l >= darkest - SPECKLE_THRESHOLD) continue;
      const around: number[] = [];
      for (let dy = -1; dy <= 1; dy++) for (let dx = -1; dx <= 1; dx++) if (dx || dy) around.push(luminance(frame, x + dx, y + dy));
      around.sort((p, q) => p - q);
      if (l < (around[3] + around[4]) / 2 - SPECKLE_THRESHOLD) {
        count++;
        where.push([x, y]);
        if (at.length < 8) at.push(`(${x}, ${y}) ${l.toFixed(2)} < ${darkest.toFixed(2)}`);
      }
    }
  }
  return { count, at, where };
}

/** Dots of one image on its own: pixels darker than each of their 8 neighbours by more than
 * SPECKLE_THRESHOLD. The reference must have none: the dotted contours that back faces drew
 * were in it too (suzanne's brow at factor 16: 4 with Catmull-Clark, 3 with Phong, before an
 * open surface's back faces were drawn depth-biased behind its front faces, src/gpu/render/renderer.ts),
 * and a dotted reference hides dots of the frame from the count above. */
function isolatedDots(img: Image): { count: number; at: string[] } {
  let count = 0;
  const at: string[] = [];
  for (let y = 1; y + 1 < img.height; y++) {
    for (let x = 1; x + 1 < img.width; x++) {
      let lightest = Infinity;
      for (let dy = -1; dy <= 1; dy++)
        for (let dx = -1; dx <= 1; dx++) if (dx || dy) lightest = Math.min(lightest, luminance(img, x + dx, y + dy));
      if (luminance(img, x, y) < lightest - SPECKLE_THRESHOLD) {
        count++;
        if (at.length < 8) at.push(`(${x}, ${y})`);
      }
    }
  }
  return { count, at };
}

/** SPECKLE_DUMP=DIR: write each case's frame, reference, and the frame with its speckles ringed in
 * red, to look at what the count counts. */
function dump(name: string, frame: Image, ref: Image, where: [number, number][]): void {
  const dir = process.env.SPECKLE_DUMP;
  if (!dir) return;
  mkdirSync(dir, { recursive: true });
  const write = (file: string, img: Image) => {
    const png = new PNG({ width: img.width, height: img.height });
    png.data.set(img.rgba);
    writeFileSync(resolve(dir, file), PNG.sync.write(png));
  };
  const marked = { ...frame, rgba: frame.rgba.slice() };
  for (const [x, y] of where) {
    for (let d = -3; d <= 3; d++) {
      for (const [px, py] of [
        [x + d, y - 3],
        [x + d, y + 3],
        [x - 3, y + d],
        [x + 3, y + d],
      ]) {
        if (px < 0 || py < 0 || px >= frame.width || py >= frame.height) continue;
        marked.rgba.set([255, 0, 0, 255], 4 * (py * frame.width + px));
      }
    }
  }
  const base = name.replace(/[^a-z0-9]+/gi, '-');
  write(`${base}-frame.png`, frame);
  write(`${base}-ref.png`, ref);
  write(`${base}-marked.png`, marked);
}

async function frozenFrame(page: Page, query: string): Promise<Image> {
  await page.goto(`/?${query}&t=0&ui=0&wire=0&cage=0`);
  await expect(page.locator('body')).toHaveAttribute('data-state', 'ready', { timeout: 120_000 });
  return decodePng(await page.locator('#view').screenshot());
}

const REFERENCE = 'mode=fixed&factor=16';

/** suzanne.obj from ../shared/cages, served to the page at this path (see the header). */
const SUZANNE = resolve(import.meta.dirname, '../../shared/cages/suzanne.obj');
const SUZANNE_URL = '/shared-cages/suzanne.obj';

/** Speckles allowed (none now), and the count before this renderer changes, where it was
 * measured (the same test, the same machine). */
const ALLOWED: Record<string, { allowed: number; before: number }> = {
  'creature mode=adaptive&surface=phong': { allowed: 0, before: 135 },
  'pawn mode=adaptive&surface=phong': { allowed: 0, before: 157 },
  'pawn mode=fixed&factor=8&surface=phong': { allowed: 0, before: 2 },
  'pawn mode=fixed&factor=8&surface=catmull-clark': { allowed: 0, before: 0 },
  'creature mode=adaptive&surface=catmull-clark': { allowed: 0, before: 5 },
  'pawn mode=adaptive&surface=catmull-clark': { allowed: 0, before: 5 },
  'suzanne mode=fixed&factor=8&surface=catmull-clark': { allowed: 0, before: 4 },
  'suzanne mode=adaptive&surface=catmull-clark': { allowed: 0, before: 58 },
  'suzanne mode=adaptive&surface=phong': { allowed: 0, before: 81 },
};

/** The references drawn so far, by query: two cases of one model and surface (pawn adaptive and
 * fixed 8; suzanne's Catmull-Clark) compare against the same frozen frame, and drawing it again at
 * factor 16 on SwiftShader costs as much as the case's own frame. The playwright config runs one
 * worker, so the cases share this module; a retry's fresh worker draws its reference again. */
const references = new Map<string, Image>();

test.describe('no isolated dark speckles against a high fixed factor', () => {
  test.use({ viewport: { width: 1000, height: 700 } });
  test.setTimeout(300_000);

  for (const key of Object.keys(ALLOWED)) {
    const [model, mode] = key.split(' ');
    const surface = mode.slice(mode.indexOf('&surface='));
    test(`${model}, ${mode}`, async ({ page }) => {
      let at = `model=${model}`;
      if (model === 'suzanne') {
        test.skip(!existsSync(SUZANNE), `${SUZANNE} is not here (the talk's cages live in ../shared/cages)`);
        const body = readFileSync(SUZANNE, 'utf8');
        await page.route(`**${SUZANNE_URL}`, (route) => route.fulfill({ body, contentType: 'text/plain' }));
        at = `model=${SUZANNE_URL}&up=y`;
      }
      const frame = await frozenFrame(page, `${at}&${mode}`);
      const refQuery = `${at}&${REFERENCE}${surface}`;
      let ref = references.get(refQuery);
      if (!ref) {
        ref = await frozenFrame(page, refQuery);
        references.set(refQuery, ref);
      }
      // The reference must show the model: a blank pair would pass trivially.
      let lit = 0;
      for (let y = 0; y < ref.height; y += 4) for (let x = 0; x < ref.width; x += 4) if (luminance(ref, x, y) > 0.3) lit++;
      expect(lit).toBeGreaterThan(500);
      const s = speckles(frame, ref);
      dump(`${model} ${mode}`, frame, ref, s.where);
      const refDots = isolatedDots(ref);
      console.log(
        `${model} ${mode}: ${s.count} speckles (before: ${ALLOWED[key].before}) ${s.at.join(' ')}; reference dots ${refDots.count}`,
      );
      expect(refDots.count, `the reference's own dots ${refDots.at.join(' ')}`).toBe(0);
      expect(s.count, s.at.join('; ')).toBeLessThanOrEqual(ALLOWED[key].allowed);
    });
  }
});
