/**
 * Shading normals at infinitely sharp creases, on the surface the demo shows by default
 * (Catmull-Clark, flat baseline on). NOT MET: this test measures a defect (issue 13, "no pixel
 * artifacts") and holds it to its present size until it is mended.
 *
 * The limit surface has two normals along an infinitely sharp crease, one per side, and a
 * normal per sector at a crease or corner vertex. The output has one: the weld
 * (wgsl/tess-weld.wgsl) evaluates every point of a cage edge through the edge's owner triangle
 * and every cage vertex through its owner, so the triangles on the other side interpolate the
 * owner side's normal. In adaptive mode, where the row next to a crease is coarse, that shows as
 * a saw-tooth band of wrong shading along the crease (seen in the demo on the sheet's fold and
 * in the gear's axle hole, 2026-11-27); at factor 16 it is a thin line.
 *
 * Measured here, on the project models with an infinitely sharp crease: of the output triangles
 * with a vertex on such a crease (a point of a sharp edge, or a cage vertex where two sharp edges
 * meet), those where such a vertex's normal is more than 45° from the triangle's geometric
 * normal, at fixed factors 4 and 16: about half of them (the other side; the worst are 78° off
 * on the sheet, 90° on the pawn and gear, 167° on the creased box). Only crease vertices are
 * counted because a strongly curved smooth region passes 45° too: the creature, which has no
 * crease, has 82 such triangles at factor 4 and 67 at 16 (the torus none; its largest is 23°).
 *
 * The mend: a second normal per side for the points of infinitely sharp edges, and one per
 * sector for crease and corner vertices (../shared/notes/catmull-clark.md §6.5: "store it per
 * face corner"). That should take every count here to 0. The factor rule wants the same
 * per-side normals: its edge term reads one normal per cage vertex.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { readdirSync, readFileSync } from 'node:fs';
import { getDevice, releaseDevice } from './gpu-device.ts';
import { tessellateOnce } from '../src/gpu/headless.ts';
import type { Tessellator } from '../src/gpu/tessellator.ts';
import { demoCcTessellator } from './demo-tessellator.ts';
import { prepareMesh } from '../src/gpu/prepare.ts';
import { buildCatmullClark } from '../src/gpu/cc/build.ts';
import { loadCage } from '../src/mesh/index.ts';
import type { MeshReadback } from '../src/gpu/readback.ts';
import type { Cage } from '../src/mesh/types.ts';
import type { PreparedMesh } from '../src/gpu/prepare.ts';
import { SHARPNESS_INFINITE } from '../src/mesh/types.ts';

const MODELS = new URL('../public/models/', import.meta.url);

/** Crease triangles with a wrong-side normal, as measured on 2026-11-27 at factors 4 and 16. */
const MEASURED: Record<string, [number, number]> = {
  'brick-box.obj': [68, 260],
  'creased-box.obj': [68, 260],
  'gear.obj': [425, 1625],
  'pawn.obj': [128, 512],
  'sheet.obj': [47, 191],
};

/** Which output vertices lie on an infinitely sharp crease, at a fixed integer factor F: the
 * output's vertex order is the cage's vertices (mesh.vertexCount, with the n-gon centres),
 * then F − 1 points per mesh edge in edge order, then the cage triangles' interiors. A cage
 * vertex counts where two or more infinitely sharp edges meet or a corner tag is infinitely
 * sharp (one such edge ending there is a dart: one normal). */
function creasePoints(cage: Cage, mesh: PreparedMesh, F: number): (v: number) => boolean {
  const key = (a: number, b: number) => (a < b ? `${a},${b}` : `${b},${a}`);
  const sharp = new Set(cage.creases.filter((c) => c.sharpness >= SHARPNESS_INFINITE).map((c) => key(c.v0, c.v1)));
  const sharpEdge = Array.from({ length: mesh.edgeCount }, (_, e) => sharp.has(key(mesh.edgeVerts[2 * e], mesh.edgeVerts[2 * e + 1])));
  const incident = new Uint32Array(mesh.vertexCount);
  sharpEdge.forEach((s, e) => {
    if (s) for (const v of [mesh.edgeVerts[2 * e], mesh.edgeVerts[2 * e + 1]]) incident[v]++;
  });
  const cornerTag = new Set(cage.corners.filter((c) => c.sharpness >= SHARPNESS_INFINITE).map((c) => c.v));
  const nV = mesh.vertexCount;
  return (v) => {
    if (v < nV) return incident[v] >= 2 || cornerTag.has(v);
    const e = Math.floor((v - nV) / (F - 1));
    return e < mesh.edgeCount && sharpEdge[e];
  };
}

/** Of the triangles with a vertex on an infinitely sharp crease: how many there are, and how
 * many have such a vertex whose normal is more than 45° from the triangle's geometric normal. */
function wrongSide(o: MeshReadback, onCrease: (v: number) => boolean): { touching: number; wrong: number } {
  const P = o.positions,
    N = o.normals;
  let n = 0;
  let touching = 0;
  for (let t = 0; t < o.triangleCount; t++) {
    const [a, b, c] = [0, 1, 2].map((i) => o.indices[3 * t + i]);
    const e1 = [0, 1, 2].map((k) => P[3 * b + k] - P[3 * a + k]);
    const e2 = [0, 1, 2].map((k) => P[3 * c + k] - P[3 * a + k]);
    const g = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    const gl = Math.hypot(g[0], g[1], g[2]);
    if (gl === 0) continue;
    if (onCrease(a) || onCrease(b) || onCrease(c)) touching++;
    const off = (v: number) => onCrease(v) && N[3 * v] * g[0] + N[3 * v + 1] * g[1] + N[3 * v + 2] * g[2] < Math.SQRT1_2 * gl;
    if (off(a) || off(b) || off(c)) n++;
  }
  return { touching, wrong: n };
}

let tess: Tessellator | undefined;
afterAll(() => {
  tess?.destroy();
  return releaseDevice();
});

describe('shading normals at infinitely sharp creases', () => {
  // The project models with an infinitely sharp crease (the others have no crease point).
  const files = readdirSync(MODELS)
    .filter((f) => f.endsWith('.obj'))
    .filter((f) => loadCage(readFileSync(new URL(f, MODELS), 'utf8')).cage.creases.some((c) => c.sharpness >= SHARPNESS_INFINITE))
    .sort();
  it('finds them', () => expect(files).toEqual(Object.keys(MEASURED).sort()));
  for (const file of files) {
    it(`${file}: fixed factors 4 and 16`, async () => {
      const device = await getDevice();
      tess ??= demoCcTessellator(device);
      const cage = loadCage(readFileSync(new URL(file, MODELS), 'utf8')).cage;
      const mesh = prepareMesh(cage);
      const prepared = { mesh, cc: buildCatmullClark(cage, mesh) };
      const counts: number[] = [];
      const touching: number[] = [];
      for (const fixedFactor of [4, 16]) {
        const r = await tessellateOnce(device, cage, { mode: 'fixed', fixedFactor, flatBaseline: true }, tess, prepared);
        // The vertex order creasePoints reads: cage vertices, F − 1 points per edge, interiors.
        expect(r.out.vertexCount).toBeGreaterThanOrEqual(mesh.vertexCount + mesh.edgeCount * (fixedFactor - 1));
        const m = wrongSide(r.out, creasePoints(cage, mesh, fixedFactor));
        counts.push(m.wrong);
        touching.push(m.touching);
      }
      console.log(`${file}: ${counts.join(' / ')} of ${touching.join(' / ')} crease triangles with a wrong-side normal (factors 4 / 16)`);
      // The measure tells the sides apart: the owner's side is never counted.
      expect(counts[0]).toBeLessThan(touching[0]);
      expect(counts[1]).toBeLessThan(touching[1]);
      const allowed = MEASURED[file];
      expect(counts[0]).toBeLessThanOrEqual(allowed[0]);
      expect(counts[1]).toBeLessThanOrEqual(allowed[1]);
    });
  }
});
