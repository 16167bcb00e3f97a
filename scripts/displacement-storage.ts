// The talk's storage table for tessellab's displaced models (public/models/displaced.json):
// `npx tsx scripts/displacement-storage.ts [--webp]`, prints a Markdown table.
//
// Tessellation: the fixed tess factor F (same factor on every edge, as `npm run tessellate --
// --fixed F`) whose output is closest to 2 triangles per USED texel, the talk's "1 texel = 2
// triangles" (Suzanne: 2K map, 64.9 % UV coverage, ~5.45 M triangles). Output triangle counts
// come from the CPU patterns: every prepared triangle (gpu/prepare.ts: quads → 2, n-gons → fan)
// emits clampedTriangle([F, F, F]).triangleCount triangles. Bits per output triangle:
//   baseline 5 B/tri = 40; raw 8-bit = 8 · (all texels of the map) / triangles, as the talk's
//   "8-bit displacement (1 B/texel)" row counts the whole map; PNG = the shipped file, plus an
//   8-bit PNG of 16-bit maps (what "8-bit is often enough" would store); WebP (with --webp):
//   lossless WebP of the 8-bit map, encoded by the system Chromium's canvas.toBlob('image/webp', 1)
//   and decoded back to check it is lossless (no WebP encoder is available to Node here without
//   a new package). The cage OBJ is a fixed cost, listed for honesty.
import { readFileSync } from 'node:fs';
import { loadCage, uvTexelCoverage } from '../src/mesh/index.ts';
import type { DisplacedModelEntry, HeightMap } from '../src/mesh/heightmap.ts';
import { decodeHeightPng, encodeHeightPng } from '../src/mesh/heightmap-png.ts';
import { prepareMesh } from '../src/gpu/tess/prepare.ts';
import { clampedTriangle } from '../src/pattern/clamped.ts';

type Entry = DisplacedModelEntry;

const dir = new URL('../public/models/', import.meta.url);
const list = JSON.parse(readFileSync(new URL('displaced.json', dir), 'utf8')) as Entry[];
const wantWebp = process.argv.includes('--webp');

const to8 = (m: HeightMap): HeightMap => (m.bits === 8 ? m : { ...m, bits: 8, data: m.data.map((x) => Math.round(x / 257)) });

/** Lossless WebP sizes of 8-bit maps via the system Chromium, or null with the reason. */
async function webpSizes(maps: HeightMap[]): Promise<{ sizes: number[] } | { error: string }> {
  try {
    const { chromium } = await import('playwright');
    const { chromiumPath } = await import('../chromium-flags.ts');
    const browser = await chromium.launch({ executablePath: chromiumPath, args: ['--no-sandbox'] });
    try {
      const page = await browser.newPage();
      const sizes: number[] = [];
      for (const m of maps) {
        const r = await page.evaluate(
          async ({ w, h, grey }) => {
            const c = new OffscreenCanvas(w, h);
            const ctx = c.getContext('2d')!;
            const img = ctx.createImageData(w, h);
            for (let p = 0; p < w * h; p++) {
              img.data[4 * p] = img.data[4 * p + 1] = img.data[4 * p + 2] = grey[p];
              img.data[4 * p + 3] = 255;
            }
            ctx.putImageData(img, 0, 0);
            const blob = await c.convertToBlob({ type: 'image/webp', quality: 1 });
            // Decode it back and compare: only a lossless encoding counts.
            const bmp = await createImageBitmap(blob, { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
            const d = new OffscreenCanvas(w, h).getContext('2d')!;
            d.drawImage(bmp, 0, 0);
            const back = d.getImageData(0, 0, w, h).data;
            let diff = 0;
            for (let p = 0; p < w * h; p++) diff = Math.max(diff, Math.abs(back[4 * p] - grey[p]));
            return { type: blob.type, size: blob.size, diff };
          },
          { w: m.width, h: m.height, grey: Array.from(m.data) },
        );
        if (r.type !== 'image/webp') return { error: `the browser encoded ${r.type}, not WebP` };
        if (r.diff !== 0) return { error: `the browser's WebP at quality 1 is not lossless (max error ${r.diff})` };
        sizes.push(r.size);
      }
      return { sizes };
    } finally {
      await browser.close();
    }
  } catch (e) {
    return { error: `no browser WebP encoder: ${(e as Error).message.split('\n')[0]}` };
  }
}

const rows: string[] = [];
const maps8: HeightMap[] = [];
const triCounts: number[] = [];
const triOf = new Map<number, number>();
for (let F = 1; F <= 64; F++) triOf.set(F, clampedTriangle([F, F, F]).triangleCount);
for (const e of list) {
  const objText = readFileSync(new URL(e.model, dir), 'utf8');
  const { cage } = loadCage(objText);
  const png = readFileSync(new URL(e.heightMap, dir));
  const map = decodeHeightPng(new Uint8Array(png));
  const { covered } = uvTexelCoverage(cage, map.width, map.height, e.wrap);
  const prepared = prepareMesh(cage).triangleCount;
  let F = 1;
  for (const [f, t] of triOf)
    if (Math.abs(Math.log((prepared * t) / (2 * covered))) < Math.abs(Math.log((prepared * triOf.get(F)!) / (2 * covered)))) F = f;
  const tris = prepared * triOf.get(F)!;
  triCounts.push(tris);
  const texels = map.width * map.height;
  const m8 = to8(map);
  maps8.push(m8);
  const png8 = map.bits === 8 ? png.length : encodeHeightPng(m8).length;
  const b = (bytes: number): string => ((8 * bytes) / tris).toFixed(2);
  rows.push(
    `| ${e.model} | ${map.width}x${map.height} ${map.bits}-bit | ${((100 * covered) / texels).toFixed(1)} % | ${F} | ${tris} | ${(tris / covered).toFixed(2)} | 40 | ${b(texels)} | ${b(png.length)} (${png.length} B) | ${map.bits === 16 ? `${b(png8)} (${png8} B)` : 'same'} | WEBP | ${b(objText.length)} |`,
  );
}
let webpNote = 'not run (pass --webp to encode in the system Chromium)';
if (wantWebp) {
  const r = await webpSizes(maps8);
  if ('sizes' in r) {
    r.sizes.forEach((s, i) => {
      rows[i] = rows[i].replace('WEBP', `${((8 * s) / triCounts[i]).toFixed(2)} (${s} B)`);
    });
    webpNote = 'lossless WebP of the 8-bit map from Chromium canvas convertToBlob(quality 1), verified lossless by decoding back';
  } else webpNote = r.error;
}
for (let i = 0; i < rows.length; i++) rows[i] = rows[i].replace('WEBP', 'n/a');
console.log(
  '| model | map | UV coverage | fixed F | output triangles | tri / used texel | baseline 5 B/tri | raw 8-bit | PNG file | PNG 8-bit | WebP lossless 8-bit | cage OBJ |',
);
console.log('|---|---|---|---|---|---|---|---|---|---|---|---|');
for (const r of rows) console.log(r);
console.log(`\nbits per output triangle. WebP: ${webpNote}.`);
