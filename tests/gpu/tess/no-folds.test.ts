/**
 * Issue 13: no folded triangles in adaptive mode. The whole adaptive pipeline on the CPU
 * (tests/support/cpu-pipeline.ts: the factor rule, the clamped pattern, the Phong surface) over every
 * project model and several seeded random cameras; no output triangle's geometric normal may
 * point against the surface normals at all three of its corners.
 *
 * The surface normals are the Phong surface's OWN normals (the cross product of its
 * derivatives), not the interpolated vertex normals that Phong tessellation shades with: those
 * disagree with the Phong geometry wherever the cage is concave, even at uniform factors
 * (measured: 515 of 72,192 triangles of the creature at fixed factor 8), so against them the
 * check could not tell a bad pattern from the surface's own shading normals. Against the own
 * normals the uniform tessellations of every model but the creature fold nothing at any factor
 * from 1 to 16 (in steps of 1/16). The creature's Phong surface folds on its own at uniform
 * factors just above 1: four of its cage triangles, at factors up to 1.4375 and at 2 (the test
 * "the creature's Phong surface still folds" below; seven, up to 3.125, before the per-edge α).
 * They lie where the legs leave the body: at the two cage vertices between the legs (x = ±1.2,
 * y = 0.75, z = 0 as stored, Y-up), whose vertex normals lie 6° from the planes of some of their faces (84° from
 * those faces' normals), and at two legs' roots (16°). Phong tessellation projects onto those
 * tangent planes, which pulls the points near such a vertex sideways, and whole rows of its
 * pattern turn over. Elsewhere a fold is the pattern's: a sliver whose three vertices lie on one
 * curve of the surface.
 *
 * MET since the Phong surface's α per edge (src/gpu/surface/phong.ts phongTriAlphas, 2026-11-27): 0 on
 * every project model over the 24 views (the creature 0 of 1,538,342; 6 of 1,614,614 before).
 * Still 0 since the models are stored Y-up (2026-11-28), which turned these views 90° about x
 * relative to them: the figures in this header are of the views before that.
 * What is left, found with views this test does not take (.scratch, not kept): 24 directions
 * (yaw 45° apart, pitch −0.8, 0, 0.8) at 17 distances 1.25× apart from 1 to 35 times the
 * model's size, LOD 1: the creature folds 164 of 9,861,132 triangles (921 of 10,333,694 with
 * α = 0.75 everywhere), in five cage triangles: 265 and 665 (factors 3 and 6-8, by the corner
 * between the legs), 522 (2.1-3.2), 274 and 642 (1.4, at 28 times its size); every other model
 * 0. Those are slivers under a pixel: at most 0.074 px wide and 0.22 px² in this test's
 * 1920 × 1080 view (half under 0.025 px²).
 * Holding each corner's Jacobian at 0.6 instead of 0.45 leaves 24 there; at 0.75 none, but
 * that lowers α on 1,306 of the creature's 1,692 edges (826 to 0.4 or less) and moves the boxes'
 * surface by 3.3 % of their size.
 *
 * HISTORY. Folds came from triangles whose three vertices lie nearly on one line in the domain
 * (a cage edge or the clamp line, curved on the surface): the gap strip is cut to avoid them
 * (src/pattern/clamped.ts: small strips exactly, stripTriangulation; large ones by the greedy
 * gapMergeSteps; the plan pass computes the cut once per cage triangle and stores it, the
 * emit pass reads it), which took the counts over six views from (creature 311, creased-box 20,
 * gear 27, icosphere 11, pawn 11) to 17 on the creature and 0 elsewhere; the factor rule's
 * contour term took the creature to 14. Over 24 views that rule folded the boxes 10 each of
 * 46,270 triangles, the gear 3 of 91,854, the creature 67 of 144,256. What was left were needles
 * along a long chord of a strongly curved cage triangle, at factors just above 1 next to edges at
 * 1, whose boundary points no triangulation joins without a fold (the last test below shows it
 * for one of them). The factor rule's bulge term (src/gpu/tess/factors.ts bulgeFactor) splits such
 * triangles from inside: boxes and gear 0, the creature 6 (with triangles facing away left out
 * of the term: the boxes 106, the gear 24, the creature 62). The creature's six lay in three
 * cage triangles at such vertices: 265 and 665 between the legs, 401 at a hind leg's root. A
 * factor rule cannot be sure to clear them: with α = 0.75, triangles 410 and 522 fold at every
 * uniform factor in (1, 2.375], so a rule that raises their three edges together from 1 to 3
 * passes through folds (whether some other order of raising them avoids all folds is not known).
 * What cleared them is the per-edge α, the last experiment below.
 * Experiments (2026-11-27, on these 24 views unless said; scratch code, not kept):
 *  - Grading each edge up to the largest factor of its two triangles' edges: 0 on these
 *    views, but 1 on 72 other seeded views (6 there without it), at 9-32 % more triangles.
 *  - Angle-weighted vertex normals: 7; in the uniform sweep from 1 to 16, 118 (triangle,
 *    factor) pairs that fold, against 86 with the present normals (all 86 below 4).
 *  - A per-vertex α, lowered from 0.75 to 0 as the vertex normal's smallest cosine to its faces'
 *    normals falls from 0.6 to 0.3 (α interpolated across the triangle, so still watertight):
 *    0 adaptive (with the present rule's factors) and 0 in the uniform sweep, on every model.
 *    A narrower ramp (0.3 to 0.1) left 9 in the sweep. But the ramp that works flattens Phong
 *    at a third of the creature's vertices and at most of the gear's: a change of surface, not
 *    of pattern, and it is not made.
 *  - α lowered only where it is needed (2026-11-27): 0.05 off at the corners of every cage
 *    triangle that folds in the uniform sweep (factors 1 to 6 in steps of 1/16), repeated until
 *    none does: 5 rounds, 19 of the creature's 566 vertices at α 0.40-0.70, the sweep clean, but
 *    adaptive still 1 (of 1,595,516 triangles). Not made either: a search of seconds per cage at
 *    load, still a change of surface, and not 0. (A rule from the surface's own normal against
 *    the vertex normals instead marked 43 triangles that are not the folding ones.)
 *  - Where the six fold (2026-11-27, second look): not in the uniform sweep's band but at
 *    factors 6 to 17, in slivers next to one corner of triangles 265, 665 and 401, whose edges'
 *    first points slide in from that corner (0.017 of the edge from it). Phong tessellation is
 *    the quadratic Bézier triangle whose edge control points are
 *        b_ij = (p_i + p_j)/2 + (α/2)·((e·n_j) n_j − (e·n_i) n_i),  e = p_j − p_i,
 *    one per EDGE, so α may differ from edge to edge and the surface stays watertight. At corner
 *    i its Jacobian, against the flat triangle's, is 1 − α·sin²θ_i (θ_i: the vertex normal's
 *    angle to the face normal): 0.26 at those corners (cos θ = 0.108 between the legs), 0.30 at
 *    the hind leg's root. The map squeezes the pattern there and the slivers turn over.
 *    Measured on these 24 views and on 72 more seeded views (.scratch, not kept; 6 and 14
 *    folds at α = 0.75):
 *      · a factor floor (3 or 4 on every edge of a triangle with some cos θ_i < 0.3 or 0.5):
 *        6 and 13; the factors there are already above it.
 *      · α per edge lowered until each triangle's six Bernstein coefficients of its Jacobian
 *        are at least τ of the flat triangle's: τ = 0.1 (8 triangles) 6 and 13, τ = 0.35: 2
 *        and 9, τ = 0.5: 0 and 0, but 646 of the creature's 1,692 edges lowered, to 0.14.
 *      · α per edge = the least over its triangles of min(0.75, (1 − τ)/max_i sin²θ_i), which
 *        holds every corner's Jacobian at τ or above: τ = 0.45: 0 and 2, 388 edges lowered (to
 *        0.55 at least), the surface moved by up to 0.29 % of the creature's size; τ = 0.5: 0
 *        and 1. The same with α = 0 on the edges of a triangle where a corner's vertex normal
 *        points away from the face (cos θ_i ≤ 0; 56 edges of the creature): 0 and 0 on every
 *        model, with 411 of the creature's edges lowered (4.8 % fewer triangles over the 96
 *        views), the boxes' 56 of 72 to 0.645, the gear's 260 of 450 to 0.573, the pawn's 128
 *        of 720 to 0.551; surfaces moved by up to 0.64 % (creature), 0.75 % (boxes), 0.52 %
 *        (gear), 0.20 % (pawn) of their size. Made (src/gpu/surface/phong.ts, PHONG_MIN_JACOBIAN = 0.45; both
 *        tessellators read the α per edge from their cage buffers); τ = 0.35 and 0.3 fold 1
 *        and 4 on these 24 views. What it leaves on other views: the paragraph MET above.
 */
import { describe, expect, it } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';
import { loadCage } from '../../../src/mesh/index.ts';
import { type PreparedMesh, prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { PHONG_ALPHA } from '../../../src/gpu/tess/factors.ts';
import {
  cameraRule,
  cpuTessellate,
  FOLD_VIEWS,
  foldCameras,
  geometricNormal,
  phongSurfaceNormal,
  type CpuTriangle,
} from '../../support/cpu-pipeline.ts';
import { phongPoint } from '../../../src/gpu/surface/phong.ts';
import { clampedTriangle, type Reverse } from '../../../src/pattern/clamped.ts';
import { ONE } from '../../../src/pattern/fixed.ts';

const MODELS = new URL('../../../public/models/', import.meta.url);

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
      expect(report).toEqual([]);
      expect(folds).toBe(0);
    });
  }

  it("the creature's Phong surface still folds at uniform factors just above 1: four cage triangles, none above 2", () => {
    const mesh = prepareMesh(loadCage(readFileSync(new URL('creature.obj', MODELS), 'utf8')).cage);
    const foldsAt = (t: number, u: number): boolean => {
      const tv = [0, 1, 2].map((i) => mesh.triVerts[3 * t + i]);
      const reverse = [0, 1, 2].map((i) => tv[i] > tv[(i + 1) % 3]) as unknown as Reverse;
      const factors: [number, number, number] = [u, u, u];
      const pat = clampedTriangle(factors, reverse);
      const w = (v: number) => [0, 1, 2].map((i) => pat.bary[3 * v + i] / ONE) as [number, number, number];
      const pts = Array.from({ length: pat.vertexCount }, (_, v) => ({
        pos: phongPoint(mesh, t, w(v)).pos,
        n: phongSurfaceNormal(mesh, t, w(v)),
      }));
      for (let k = 0; k < pat.triangleCount; k++) {
        const c = [0, 1, 2].map((i) => pts[pat.triangles[3 * k + i]]);
        if (folded({ p: [c[0].pos, c[1].pos, c[2].pos], n: [c[0].n, c[1].n, c[2].n], cageTri: t, factors, reverse, local: k })) return true;
      }
      return false;
    };
    // Factors 1 to 4 in steps of 1/16 (16.16-exact), and the cage triangles that fold at each.
    const bands = new Map<number, number[]>();
    for (let u = 1; u <= 4; u += 1 / 16)
      for (let t = 0; t < mesh.triangleCount; t++)
        if (foldsAt(t, u)) {
          if (!bands.has(t)) bands.set(t, []);
          bands.get(t)?.push(u);
        }
    const range = (lo: number, hi: number) => Array.from({ length: Math.round((hi - lo) * 16) + 1 }, (_, i) => lo + i / 16);
    // Pairs alike by the body's symmetry (their reverse flags, so their patterns, differ):
    // 410/522 at the vertices between the hind and the front legs, 274/642 at a hind and a front
    // leg's root. With α = 0.75 on every edge (before the per-edge α) seven triangles folded,
    // 410 at every factor in (1, 2.375] and 265/665 in [2.4375, 3.125].
    expect(Object.fromEntries(bands)).toEqual({
      274: range(1.0625, 1.125),
      410: [...range(1.0625, 1.4375), 2],
      522: [...range(1.0625, 1.4375), 2],
      642: range(1.0625, 1.125),
    });
  });

  it('creature, cage triangle 367 at factors (1.077, 1, 1): with α = 0.75 every triangulation of its pattern vertices folds; with its α per edge its pattern does not', () => {
    // Its factors there (16.16-exact) and reverse flags, as the first camera gave them with
    // α = 0.75: edge 0 has two points near its ends, edges 1 and 2 none. Its corner normals lie
    // almost in the cage triangle's plane (cos θ = 0.044 at one), so Phong tessellation bends
    // hard near that corner; the per-edge α (src/gpu/surface/phong.ts) lowers its edges to 0.55.
    const mesh = prepareMesh(loadCage(readFileSync(new URL('creature.obj', MODELS), 'utf8')).cage);
    const uniform = { ...mesh, triPhongAlpha: new Float32Array(mesh.triPhongAlpha.length).fill(PHONG_ALPHA) };
    const t = 367;
    const factors: [number, number, number] = [1.0765380859375, 1, 1];
    const reverse: Reverse = [false, true, true];
    const tv = [0, 1, 2].map((i) => mesh.triVerts[3 * t + i]);
    expect([0, 1, 2].map((i) => tv[i] > tv[(i + 1) % 3])).toEqual(reverse);
    expect([...mesh.triPhongAlpha.subarray(3 * t, 3 * t + 3)].every((a) => a < 0.56)).toBe(true);
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
    const foldsPerFan = (m: PreparedMesh) => {
      const pts = ring.map((v) => ({ pos: phongPoint(m, t, w(v)).pos, n: phongSurfaceNormal(m, t, w(v)) }));
      const folds = (i: number, j: number, k: number) =>
        folded({ p: [pts[i].pos, pts[j].pos, pts[k].pos], n: [pts[i].n, pts[j].n, pts[k].n], cageTri: t, factors, reverse, local: 0 });
      // The five triangulations of a convex pentagon are the fans from each of its corners.
      return [0, 1, 2, 3, 4].map((o) => [1, 2, 3].filter((s) => folds(o, (o + s) % 5, (o + s + 1) % 5)).length);
    };
    expect(foldsPerFan(uniform).every((f) => f >= 1)).toBe(true);
    // The pattern's own triangles, on the surface with its α per edge.
    const pts = Array.from({ length: pat.vertexCount }, (_, v) => ({
      pos: phongPoint(mesh, t, w(v)).pos,
      n: phongSurfaceNormal(mesh, t, w(v)),
    }));
    for (let k = 0; k < pat.triangleCount; k++) {
      const c = [0, 1, 2].map((i) => pts[pat.triangles[3 * k + i]]);
      expect(folded({ p: [c[0].pos, c[1].pos, c[2].pos], n: [c[0].n, c[1].n, c[2].n], cageTri: t, factors, reverse, local: k })).toBe(
        false,
      );
    }
  });
});
