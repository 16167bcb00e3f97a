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
 * NOT MET: zero, and not reachable with the pattern's vertices. Folds come from triangles whose
 * three vertices lie nearly on one line in the domain (a cage edge or the clamp line, curved on
 * the surface), and from needles along a long chord of a strongly curved cage triangle. The gap
 * strip is cut by a cap-avoiding greedy (src/pattern/clamped.ts gapMergeSteps; the plan pass
 * makes its moves once per cage triangle and stores them, the emit pass reads them), which took
 * the counts from (creature 311, creased-box 20, gear 27, icosphere 11, pawn 11) to the ones
 * below. What is left cannot all go: e.g. creature, camera 0, cage triangle 367 at factors
 * (1.0765, 1, 1): its vertices are the three corners and edge 0's two points near its ends, and
 * every one of the five triangulations of those five points folds a triangle (its corner normals
 * lie almost in the cage triangle's plane: 0.04 and 0.08 from it), so no split rule over these
 * vertices reaches zero there. This is a ratchet at the counts measured now: a change that folds
 * more fails.
 */
import { describe, expect, it } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';
import { loadCage } from '../src/mesh/index.ts';
import { prepareMesh } from '../src/gpu/prepare.ts';
import type { Vec3 } from '../src/gpu/factors.ts';
import { cameraRule, cpuTessellate, geometricNormal, type CpuTriangle } from './cpu-pipeline.ts';

const MODELS = new URL('../public/models/', import.meta.url);

/** Folded triangles allowed over the 6 cameras (all others: 0), as measured with today's pattern. */
const RESIDUAL: Record<string, { allowed: number }> = {
  'creature.obj': { allowed: 26 },
  'creature-wrinkles.obj': { allowed: 26 }, // the creature's cage with UVs
  'pawn.obj': { allowed: 5 },
};

/** A small deterministic generator (LCG), so the cameras are the same on every run. */
function lcg(seed: number): () => number {
  let s = seed;
  return () => (s = (s * 1103515245 + 12345) % 2147483648) / 2147483648;
}

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
    it(`${file}: over 6 random cameras and LOD scales 0.5, 1, 2`, () => {
      const mesh = prepareMesh(loadCage(readFileSync(new URL(file, MODELS), 'utf8')).cage);
      const centre: Vec3 = [0, 1, 2].map((i) => (mesh.bboxMin[i] + mesh.bboxMax[i]) / 2) as unknown as Vec3;
      const rnd = lcg(12345);
      const report: string[] = [];
      let total = 0;
      let folds = 0;
      for (let cam = 0; cam < 6; cam++) {
        const yaw = rnd() * 2 * Math.PI,
          pitch = (rnd() - 0.5) * 2.4,
          dist = mesh.size * (0.6 + 1.4 * rnd());
        const eye: Vec3 = [
          centre[0] + dist * Math.cos(pitch) * Math.sin(yaw),
          centre[1] + dist * Math.sin(pitch),
          centre[2] + dist * Math.cos(pitch) * Math.cos(yaw),
        ];
        const tris = cpuTessellate(mesh, cameraRule('adaptive', eye, centre, mesh.size, { lodScale: [0.5, 1, 2][cam % 3] }), true);
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
      expect(total).toBeGreaterThan(0);
      const allowed = RESIDUAL[file]?.allowed ?? 0;
      if (folds > allowed || allowed === 0) expect(report).toEqual([]);
      expect(folds).toBeLessThanOrEqual(allowed);
    });
  }
});
