/**
 * Issue 13's smooth default: in the demo's first view (adaptive, LOD 1, the flat-baseline blend
 * on, as the demo starts), no output vertex that faces the eye is more than a pixel from the exact
 * limit surface (scripts/limit-distance.ts: distance to the exact CPU reference at the vertex's
 * cage parameter, over the size of a pixel at its distance from the eye). Before the blend was
 * bounded (wgsl/surface-cc.wgsl evalSurface) the same measure read 3.4 px on the creature, 3.3 on
 * the pawn, 5.4 on bigguy and 5.2 on suzanne. Also at LOD 2 (bound ½ px) on one model.
 *
 * NOT MET: the drawn triangles between the vertices (scripts/limit-distance.ts
 * displayedDistancePx: every output edge's midpoint and triangle's centroid against the limit
 * at the mean cage parameter, along the limit normal) are not within 1 px: the blend's pixel
 * at the vertices and the chord's sag between them add, Hable's line has segments longer than
 * 1/F inside an octave (src/gpu/factors.ts: up to (L·F)² = 2 in [4, 8]), and the Phong estimate
 * of the factor rule misses part of the limit's curvature (on the cage triangles whose edges
 * are all below factor 1.5, the limit's bulge at the centroid is up to 3.6× the Phong estimate's
 * there). DISPLAYED_MAX is a ratchet at what is measured now.
 * Of the samples over 1 px, nearly all lie where every edge of the cage triangle is below factor
 * 4 (the flat baseline's band) and inside the cage triangle. Tried and not taken: the factor rule
 * sampling the limit's own edge curve (¼, ½, ¾) instead of the Phong estimate (23–97% more
 * triangles, the maxima no lower: points inside the cage triangles dominate); the blend
 * bounded at ½ px (the pop test's creased box 4.9e-3 > 4e-3; the p99 fell by about 0.2 px, the
 * maxima hardly).
 * Also tried (2026-11-27; maxima creature/pawn/bigguy/suzanne, against 2.56/3.02/2.58/4.70 px):
 * - every edge also takes its two triangles' centroid term, k = sqrt(α·lod·bulge), the bulge
 *   being the limit at the centroid minus the flat triangle's, in px: α = 1: +15–46% triangles
 *   and the maxima UP (3.79/3.19/3.28/4.40), because the clamped pattern has no interior vertex
 *   below factor 3 or so and an output edge then runs across the bulge from edge point to edge
 *   point; α = 2: +40–84%, 1.91/2.45/3.03/3.10; α = 4: ×1.8–2.6, 1.70/1.56/1.69/3.10 (p99 ≤ 1.09)
 *   but the pop test's ×1.06 sweep fails (creased box 4.96e-3; α = 3: 4.58e-3), by moving faster,
 *   not by popping (tests/cc-animate.gpu.test.ts's jump test passes: 1.0e-4 and 1.2e-5); α = 4 with chord and blend
 *   each held to ½ px: ×3.3–4.5, 1.28/1.38/1.19/2.39. The bulge's part that the edges' midpoints
 *   do not predict (β·residual, β = 16): +59–113%, no better. The limit's own midpoint on every
 *   edge: +13–40%, maxima unchanged.
 * - on crease and boundary edges only, the limit's midpoint and no culling by the end normals.
 *   The pawn's base rim is a crease whose vertex normals (the limit's, one side's) are the
 *   bottom's: the factor rule reads the rim as facing away, factor 1, while its side faces the
 *   eye, so the rim's outline is the cage's 16-gon, 2.9 px off the limit. With the change 1.3 px,
 *   and over 40 extra fold views fewer folds (gear 11 → 5, boxes 4 → 1), but in the frame the rim
 *   turned ragged (the flat baseline interpolates the same one-sided vertex normals, and the bottom
 *   fan shows under the new points) and the pawn's speckles went 4 → 5: not taken. A crease needs
 *   its two sides' normals (split vertices) before its factor can rise.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { existsSync, readFileSync } from 'node:fs';
import { getDevice, releaseDevice } from './gpu-device.ts';
import { tessellateOnce } from '../src/gpu/headless.ts';
import type { Tessellator } from '../src/gpu/tessellator.ts';
import { demoCcTessellator } from './demo-tessellator.ts';
import { prepareMesh } from '../src/gpu/prepare.ts';
import { loadCage } from '../src/mesh/index.ts';
import { demoView, displayedDistancePx, limitDistancePx } from '../scripts/limit-distance.ts';

/** The displayed surface's largest distance (px) from the limit, as measured (NOT MET: 1 / LOD). */
const DISPLAYED_MAX: Record<string, number> = {
  'creature.obj LOD 1': 2.57,
  'pawn.obj LOD 1': 3.02,
  'pawn.obj LOD 2': 2.91,
  'bigguy.obj LOD 1': 2.57,
  'suzanne.obj LOD 1': 4.71,
};

/** f32 evaluation against the f64 reference: far below a pixel at these distances. */
const SLACK = 1e-3;

let tess: Tessellator | undefined;
afterAll(() => {
  tess?.destroy();
  return releaseDevice();
});

const models: [string, number][] = [
  ['public/models/creature.obj', 1],
  ['public/models/pawn.obj', 1],
  ['public/models/pawn.obj', 2],
];
for (const name of ['bigguy', 'suzanne']) if (existsSync(`../shared/cages/${name}.obj`)) models.push([`../shared/cages/${name}.obj`, 1]);

describe('the default view is within a pixel of the limit surface', () => {
  for (const [file, lodScale] of models) {
    it(`${file.split('/').pop()}, LOD ${lodScale}: every vertex facing the eye within ${1 / lodScale} px of the exact limit`, async () => {
      const device = await getDevice();
      // One tessellator for every model: its pipelines compile once.
      tess ??= demoCcTessellator(device);
      const cage = loadCage(readFileSync(file, 'utf8')).cage;
      const mesh = prepareMesh(cage);
      const view = demoView(mesh);
      const r = await tessellateOnce(
        device,
        cage,
        {
          mode: 'adaptive',
          lodScale,
          flatBaseline: true,
          eye: view.eye,
          target: view.target,
          fovY: view.fovY,
          viewportHeight: view.viewportHeight,
        },
        tess,
        { mesh },
      );
      const d = limitDistancePx(cage, mesh, r.out, view);
      console.log(file, `LOD ${lodScale}`, JSON.stringify(d));
      expect(d.count).toBeGreaterThan(500);
      expect(d.maxPx, d.worst).toBeLessThanOrEqual(1 / lodScale + SLACK);
      const shown = displayedDistancePx(cage, mesh, r.out, view);
      const key = `${file.split('/').pop()} LOD ${lodScale}`;
      console.log(key, 'displayed', JSON.stringify(shown));
      expect(shown.skipped).toBe(0);
      expect(shown.count).toBeGreaterThan(2 * d.count);
      expect(shown.maxPx, shown.worst).toBeLessThanOrEqual(DISPLAYED_MAX[key]);
    }, 120_000);
  }
});
