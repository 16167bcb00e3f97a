/**
 * No folded triangle in the models a user opens (issue 34): the GPU's own output (Dawn in Node), a
 * triangle FOLDED when its geometric normal points against the sum of its corners' normals
 * (scripts/folds.ts foldedTriangles says why; the older criterion, against all three, is the
 * second count), adaptive, from the views of scripts/folds.ts foldViews: the 24 seeded cameras
 * round the model at LOD 0.5, 1 and 2 in turn, and the CLI's and the demo's first view at LOD 0.5,
 * 1 and 2.
 *
 * What CI holds (the whole census, `npm run folds`, takes about ten minutes on two cores; the
 * closing notes of issue 34 carry its table):
 *  - the exact surface as the demo shows it (flat baseline on) on every project model at all 30
 *    views, and at fixed factor 8 (against all three: the n-gons' fans once folded 124 there);
 *    the brick box and the creature with wrinkles are the creased box and the creature with a
 *    height map, and displacement has its own checks (tests/gpu/tess/displacement.node.test.ts);
 *  - the exact surface on the talk's four models (../shared/cages, when present) at the six
 *    default views;
 *  - each ACC scheme and Phong on the project models they take at the six default views.
 * Each count is held at or below what it is now (FOLDS), 0 where it is 0.
 *
 * What the counts were, and why (over the 30 views, exact surface, flat baseline):
 *  - Hairpins: a thin fold of the cage gives the limit surface a turn of 90-150° across a strip a
 *    few hundredths of a face wide, which one row of the pattern spanned (bigguy 746, the creature
 *    130, monsterfrog 87). The factor rule's turn term (wgsl/tess/factor-bulge.wgsl) resolves it:
 *    bigguy 101, the creature 68, monsterfrog and imrod below; the folds left there are where a
 *    hairpin is narrower than the turn term's sample step or its edges are capped by pixels.
 *  - The ACC schemes' creases: the far side of every crease took the owner side's normal (the
 *    creased box 85-237 per scheme); now 0 (tests/gpu/acc/crease-normals.node.test.ts).
 *  - Needles: a row or point born next to an edge or a corner (Hable's pattern is pop-free
 *    because points are born there and slide in) makes a triangle with one edge thousands of
 *    times shorter than the others; where the surface curves across it, or at a cone point
 *    (the boxes' tagged corner, which has no limit normal), or across the kink of an n-gon's
 *    kite parametrization (imrod, all triangles), it turns over. Not removed yet: issue 34's open
 *    work.
 */
import { afterAll, describe, expect, it } from 'vitest';
import { existsSync, readFileSync } from 'node:fs';
import { getDevice, releaseDevice } from '../../support/gpu-device.ts';
import { tessellateOnce } from '../../../src/gpu/tess/headless.ts';
import { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { loadCage } from '../../../src/mesh/index.ts';
import { bakeTables } from '../../../src/pattern/tables.ts';
import { releaseSurfaceData, type SurfaceId, surfaceScheme } from '../../../src/gpu/surface/registry.ts';
import { foldedTriangles, foldsOverViews, foldViews } from '../../../scripts/folds.ts';

const MODELS = new URL('../../../public/models/', import.meta.url);
const SHARED = new URL('../../../../shared/cages/', import.meta.url);

/** Folded triangles (against the sum) now, per surface and model, summed over the views held
 * (the project models' 30 with the exact surface, else the six default views); absent: 0. Before
 * the turn term and the ACC schemes' split creases the exact surface folded the creature 130 times
 * over its 30 views (now 68) and bigguy 32 times in the CLI's view alone; Phong is unchanged
 * (issue 34 asks only that it does not rise: the creature's are where its vertex normals lie far
 * from its faces' planes, tests/gpu/tess/no-folds.test.ts). */
const FOLDS: Partial<Record<SurfaceId, Record<string, number>>> = {
  'catmull-clark': { 'creased-box': 1, creature: 68, suzanne: 3, bigguy: 25, monsterfrog: 15, imrod: 13 },
  // The boxes' 3: at their tagged corner, a cone point once its sharpness has decayed in accCage's
  // steps (0 before the steps, whose σ rounded to ∞ kept the corner), in the CLI's view at LOD 0.5.
  'bezier-acc': { creature: 11, 'creased-box': 3 },
  'gregory-acc': { creature: 8 },
  'pm-acc': { creature: 12 },
  phong: { creature: 634, gear: 1 },
};

const ALL_VIEWS = ['creased-box', 'creature', 'gear', 'icosphere', 'pawn', 'sheet', 'torus'];
const TALK = ['suzanne', 'bigguy', 'monsterfrog', 'imrod'];
/** Every project model: the ACC schemes take them all (n-gons and semi-sharp creases after accCage's steps). */
const ACC_TAKES = ALL_VIEWS;
/** The models the ACC schemes take since their Catmull-Clark steps (n-gons), and the largest: held
 * at LOD 1's two default views only (CI time; the census, `npm run folds`, runs all 30). */
const LOD1_ONLY = new Set(['gear', 'icosphere', 'pawn']);

const defaultViews = (views: ReturnType<typeof foldViews>) => views.filter((v) => !v.name.startsWith('seeded'));

afterAll(() => releaseDevice());

async function census(surface: SurfaceId, models: { name: string; path: URL }[], allViews: boolean, fixed8 = false): Promise<void> {
  const device = await getDevice();
  const tess = Tessellator.create(device, bakeTables(64), {
    surface,
    flatBaseline: true,
    vertexCapacity: 1 << 21,
    triangleCapacity: 1 << 21,
  });
  try {
    for (const { name, path } of models) {
      // The cage the surface tessellates, as the demo and the CLI give it (an ACC scheme's steps
      // for n-gons and semi-sharp creases: src/subdiv/acc.ts accCage).
      const cage = surfaceScheme(surface).surfaceCage(loadCage(readFileSync(path, 'utf8')).cage).cage;
      const mesh = prepareMesh(cage);
      const data = surfaceScheme(surface).prepare(device, cage, mesh);
      try {
        let views = allViews ? foldViews(mesh) : defaultViews(foldViews(mesh));
        if (!allViews && surface !== 'phong' && LOD1_ONLY.has(name)) views = views.filter((v) => v.name.endsWith('LOD 1'));
        const f = await foldsOverViews(device, tess, cage, { mesh, ...data }, surface, true, views);
        const where = f.where.join('; ');
        console.log(
          `${surface} ${name}, ${views.length} views: ${f.againstSum} folded (${f.againstAll} against all three) of ${f.triangles}; ${where}`,
        );
        expect(f.triangles).toBeGreaterThan(0);
        expect(f.againstSum, `${surface} ${name}: ${where}`).toBeLessThanOrEqual(FOLDS[surface]?.[name] ?? 0);
        if (fixed8) {
          const r = await tessellateOnce(device, cage, { mode: 'fixed', fixedFactor: 8, surface, flatBaseline: true }, tess, {
            mesh,
            ...data,
          });
          expect(foldedTriangles(r.out).againstAll, `${name} at fixed factor 8`).toBe(0);
        }
      } finally {
        releaseSurfaceData(data);
      }
    }
  } finally {
    tess.destroy();
  }
}

const project = (names: string[]) => names.map((name) => ({ name, path: new URL(`${name}.obj`, MODELS) }));

describe('folded triangles in the models a user opens', () => {
  for (const name of ALL_VIEWS)
    it(`exact surface, ${name}: the 30 views, and fixed factor 8`, () => census('catmull-clark', project([name]), true, true));

  const talk = TALK.filter((m) => existsSync(new URL(`${m}.obj`, SHARED)));
  it.skipIf(talk.length === 0)("exact surface, the talk's models: the six default views", () =>
    census(
      'catmull-clark',
      talk.map((name) => ({ name, path: new URL(`${name}.obj`, SHARED) })),
      false,
    ),
  );

  for (const surface of ['bezier-acc', 'gregory-acc', 'pm-acc'] as const)
    it(`${surface}: every project model after accCage's steps, the six default views (LOD 1's two on gear, icosphere, pawn)`, () =>
      census(surface, project(ACC_TAKES), false));
  it('phong: every project model, the six default views', () => census('phong', project(ALL_VIEWS), false));
});
