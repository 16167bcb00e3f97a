/**
 * Issue 13's check in its own words, on the surface the demo shows by default (Catmull-Clark,
 * adaptive, flat baseline on): no output triangle's geometric normal may oppose the output
 * normals at all three of its corners. The GPU's own output is checked here (Dawn in Node); the
 * CPU twin for Phong tessellation is tests/gpu/tess/no-folds.test.ts, which measures against the Phong
 * surface's own normals. The cameras are that test's: 24 seeded random views, LOD scales 0.5,
 * 1 and 2.
 *
 * At a fixed factor no model folds. It used to: the pawn's 16-gon base and the gear's 7-gons,
 * fanned from corner 0, folded 124 and 125 triangles at factor 8 (slivers across the n-gon's
 * centre, where Catmull-Clark's parametrization is singular; src/gpu/tess/prepare.ts says why). They
 * are now fanned round their centre, which took those to 0 and the gear's adaptive 492 to 0.
 *
 * Adaptive mode folds none over the 24 views, since the factor rule's bulge term
 * (src/gpu/tess/factors.ts, wgsl/tess/factor-bulge.wgsl). Before it: the creature 24 of 136,822 triangles,
 * the gear 14 of 109,226, the icosphere 2 of 39,184, the other models 0 (over six views only the
 * creature folded, 7: the zeros of six views were the luck of the views). Those folds were
 * needles along a cage edge: a corner, the opposite corner, and the first point of an edge that
 * had just begun to split, where the edge's curve leaves the corner on the far side of the
 * needle's line (the Phong twin, tests/gpu/tess/no-folds.test.ts, shows that no triangulation of such a
 * triangle's boundary points avoids the fold). The bulge term splits such strongly curved
 * triangles from inside, on every triangle on screen whichever way it faces (with triangles
 * facing away left out of the term the creature still folded 18, the gear 3, the icosphere 8,
 * the boxes 14: an edge at 1 beside edges at 14).
 */
import { describe, it, expect, afterAll } from 'vitest';
import { readdirSync, readFileSync } from 'node:fs';
import { getDevice, releaseDevice } from '../../support/gpu-device.ts';
import { tessellateOnce } from '../../../src/gpu/tess/headless.ts';
import type { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { demoCcTessellator } from '../../support/demo-tessellator.ts';
import { FOLD_VIEWS, foldCameras } from '../../support/cpu-pipeline.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { type Cage, loadCage, turnUpAxis } from '../../../src/mesh/index.ts';
import type { MeshReadback } from '../../../src/gpu/device/readback.ts';

const MODELS = new URL('../../../public/models/', import.meta.url);

/** The triangles whose geometric normal opposes the output normal at all three corners. */
function flagged(o: MeshReadback): number {
  const P = o.positions,
    N = o.normals;
  let n = 0;
  for (let t = 0; t < o.triangleCount; t++) {
    const [a, b, c] = [0, 1, 2].map((i) => o.indices[3 * t + i]);
    const e1 = [0, 1, 2].map((k) => P[3 * b + k] - P[3 * a + k]);
    const e2 = [0, 1, 2].map((k) => P[3 * c + k] - P[3 * a + k]);
    const g = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    if ([a, b, c].every((v) => N[3 * v] * g[0] + N[3 * v + 1] * g[1] + N[3 * v + 2] * g[2] < 0)) n++;
  }
  return n;
}

/**
 * The views were drawn round the models as they were stored until 2026-11-28, Z-up; they are now
 * stored Y-up ((x, y, z) → (x, z, −y)), and turned back here so that the 24 views stay the ones
 * this test has held to 0 (the rotation is exact). Turned with the models, the same seeded views
 * flag 3 of 1,481,518 triangles on the creature (and its displaced twin): folds of the exact
 * surface on other views, issue 34's open work, not a change of this check.
 */
function asDrawnForTheseViews(cage: Cage): Cage {
  return turnUpAxis(cage, 'z-up');
}

let tess: Tessellator | undefined;
afterAll(() => {
  tess?.destroy();
  return releaseDevice();
});

describe('Catmull-Clark as the demo shows it: no folded output triangles', () => {
  const files = readdirSync(MODELS)
    .filter((f) => f.endsWith('.obj'))
    .sort();
  for (const file of files) {
    it(`${file}: ${FOLD_VIEWS} random cameras in adaptive mode, and fixed factor 8`, async () => {
      const device = await getDevice();
      tess ??= demoCcTessellator(device);
      const cage = asDrawnForTheseViews(loadCage(readFileSync(new URL(file, MODELS), 'utf8')).cage);
      const mesh = prepareMesh(cage);
      const prepared = { mesh, cc: buildCatmullClark(cage, mesh) };
      let adaptive = 0;
      let total = 0;
      for (const { eye, target, lodScale } of foldCameras(mesh)) {
        const r = await tessellateOnce(
          device,
          cage,
          { mode: 'adaptive', flatBaseline: true, lodScale, eye: [...eye], target: [...target], fovY: Math.PI / 4, viewportHeight: 1080 },
          tess,
          prepared,
        );
        adaptive += flagged(r.out);
        total += r.out.triangleCount;
      }
      const fixed = await tessellateOnce(device, cage, { mode: 'fixed', fixedFactor: 8, flatBaseline: true }, tess, prepared);
      const fixed8 = flagged(fixed.out);
      console.log(`${file}: adaptive ${adaptive} of ${total} flagged, fixed 8 ${fixed8} of ${fixed.out.triangleCount}`);
      expect(total).toBeGreaterThan(0);
      expect(adaptive).toBe(0);
      expect(fixed8).toBe(0);
    });
  }
});
