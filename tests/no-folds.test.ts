/**
 * Issue 13: no folded triangles in adaptive mode. The whole adaptive pipeline on the CPU
 * (tests/cpu-pipeline.ts: the factor rule, the clamped pattern, the Phong surface) over every
 * project model and several seeded random cameras; no output triangle's geometric normal may
 * point against the surface normals at all three of its corners.
 *
 * The surface normals are the Phong surface's OWN normals (the cross product of its
 * derivatives), not the interpolated vertex normals that Phong tessellation shades with: those
 * disagree with the Phong geometry wherever the cage is concave, even at uniform factors
 * (measured: 515 of 72,192 triangles of the creature at fixed factor 8), so against them the
 * check could not tell a bad pattern from the surface's own shading normals. Against the own
 * normals every uniform tessellation passes (factors 1, 2, 8, 32 give no fold on any model), so
 * a fold is the pattern's: a sliver whose three vertices lie on one curve of the surface.
 *
 * NOT MET: zero on the creature (6 of 1,614,614 triangles over the 24 views); every other
 * project model folds none. Folds came from triangles whose three vertices lie nearly on one line
 * in the domain (a cage edge or the clamp line, curved on the surface): the gap strip is cut to
 * avoid them (src/pattern/clamped.ts: small strips exactly, stripTriangulation; large ones by the
 * greedy gapMergeSteps; the plan pass computes the cut once per cage triangle and stores it, the
 * emit pass reads it), which took the counts over six views from (creature 311, creased-box 20,
 * gear 27, icosphere 11, pawn 11) to 17 on the creature and 0 elsewhere; the factor rule's
 * contour term took the creature to 14. Over 24 views that rule folded the boxes 10 each of
 * 46,270 triangles, the gear 3 of 91,854, the creature 67 of 144,256. What was left were needles
 * along a long chord of a strongly curved cage triangle, at factors just above 1 next to edges at
 * 1, whose boundary points no triangulation joins without a fold (the last test below shows it
 * for one of them). The factor rule's bulge term (src/gpu/factors.ts bulgeFactor) splits such
 * triangles from inside: boxes and gear 0, the creature 6 (with triangles facing away left out
 * of the term: the boxes 106, the gear 24, the creature 62). The creature's count is a ratchet.
 */
import { describe, expect, it } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';
import { loadCage } from '../src/mesh/index.ts';
import { prepareMesh } from '../src/gpu/prepare.ts';
import {
  cameraRule,
  cpuTessellate,
  FOLD_VIEWS,
  foldCameras,
  geometricNormal,
  phongSurfaceNormal,
  type CpuTriangle,
} from './cpu-pipeline.ts';
import { phongPoint } from '../src/gpu/phong.ts';
import { clampedTriangle, type Reverse } from '../src/pattern/clamped.ts';
import { ONE } from '../src/pattern/fixed.ts';

const MODELS = new URL('../public/models/', import.meta.url);

/** Folded triangles allowed over the FOLD_VIEWS views (all others: 0), as measured. */
const RESIDUAL: Record<string, { allowed: number }> = {
  'creature.obj': { allowed: 6 },
  'creature-wrinkles.obj': { allowed: 6 }, // the creature's cage with UVs
};

function folded(t: CpuTriangle): boolean {
  const g = geometricNormal(t);
  return t.n.every((n) => n[0] * g[0] + n[1] * g[1] + n[2] * g[2] < 0);
}

describe('adaptive tessellation has no folded triangles', () => {
  const files = readdirSync(MODELS)
    .filter((f) => f.endsWith('.obj'))
    .sort();
  it('finds the project models', () => expect(files.length).toBeGreaterThanOrEqual(5));

  for (const file of files) {
    it(`${file}: over ${FOLD_VIEWS} random cameras and LOD scales 0.5, 1, 2`, () => {
      const mesh = prepareMesh(loadCage(readFileSync(new URL(file, MODELS), 'utf8')).cage);
      const report: string[] = [];
      let total = 0;
      let folds = 0;
      for (const [cam, { eye, target, lodScale }] of foldCameras(mesh).entries()) {
        const tris = cpuTessellate(mesh, cameraRule('adaptive', eye, target, mesh.size, { lodScale }), true);
        const bad = tris.filter(folded);
        total += tris.length;
        folds += bad.length;
        if (bad.length) {
          const b = bad[0];
          report.push(
            `camera ${cam}: ${bad.length} of ${tris.length} folded, e.g. cage triangle ${b.cageTri} factors ${b.factors.map((f) => f.toFixed(3))} reverse ${b.reverse.map(Number).join('')} pattern triangle ${b.local}`,
          );
        }
      }
      console.log(`${file}: ${folds} of ${total} folded`);
      expect(total).toBeGreaterThan(0);
      const allowed = RESIDUAL[file]?.allowed ?? 0;
      if (folds > allowed || allowed === 0) expect(report).toEqual([]);
      expect(folds).toBeLessThanOrEqual(allowed);
    });
  }

  it('creature, camera 0, cage triangle 367: every triangulation of its pattern vertices folds', () => {
    // Its factors there (16.16-exact) and reverse flags, as the first camera gives them: edge 0
    // has two points near its ends, edges 1 and 2 none. Its corner normals lie almost in the cage
    // triangle's plane, so Phong tessellation bends hard near corner 0.
    const mesh = prepareMesh(loadCage(readFileSync(new URL('creature.obj', MODELS), 'utf8')).cage);
    const t = 367;
    const factors: [number, number, number] = [1.0765380859375, 1, 1];
    const reverse: Reverse = [false, true, true];
    const tv = [0, 1, 2].map((i) => mesh.triVerts[3 * t + i]);
    expect([0, 1, 2].map((i) => tv[i] > tv[(i + 1) % 3])).toEqual(reverse);
    const pat = clampedTriangle(factors, reverse);
    expect(pat.vertexCount).toBe(5);
    // The five points around the triangle (all on its boundary), counter-clockwise in the
    // barycentric plane: by the angle around the centroid.
    const w = (v: number) => [0, 1, 2].map((i) => pat.bary[3 * v + i] / ONE) as [number, number, number];
    const angle = (v: number) => {
      const [, b, c] = w(v);
      return Math.atan2(c - 1 / 3, b - 1 / 3);
    };
    const ring = [0, 1, 2, 3, 4].sort((a, b) => angle(a) - angle(b));
    const pts = ring.map((v) => ({ pos: phongPoint(mesh, t, w(v)).pos, n: phongSurfaceNormal(mesh, t, w(v)) }));
    const folds = (i: number, j: number, k: number) =>
      folded({ p: [pts[i].pos, pts[j].pos, pts[k].pos], n: [pts[i].n, pts[j].n, pts[k].n], cageTri: t, factors, reverse, local: 0 });
    // The five triangulations of a convex pentagon are the fans from each of its corners.
    const foldsPerFan = [0, 1, 2, 3, 4].map((o) => [1, 2, 3].filter((s) => folds(o, (o + s) % 5, (o + s + 1) % 5)).length);
    expect(foldsPerFan.every((f) => f >= 1)).toBe(true);
    // At factor 1 everywhere (the cage triangle itself) it does not fold: the points near the
    // corner are what no triangle can join without folding.
    const corner = [0, 1, 2].map((i) => [0, 1, 2].map((k) => (k === i ? 1 : 0)) as [number, number, number]);
    const at = corner.map((c) => ({ pos: phongPoint(mesh, t, c).pos, n: phongSurfaceNormal(mesh, t, c) }));
    expect(folded({ p: [at[0].pos, at[1].pos, at[2].pos], n: [at[0].n, at[1].n, at[2].n], cageTri: t, factors, reverse, local: 0 })).toBe(
      false,
    );
  });
});
