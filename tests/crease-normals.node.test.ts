/**
 * Shading normals at infinitely sharp creases, on the surface the demo shows by default
 * (Catmull-Clark, flat baseline on). The limit surface has two normals along an infinitely sharp
 * crease, one per side, and one per sector at a vertex where such creases meet (per face at an
 * infinitely sharp corner tag). With one output vertex per point the weld (wgsl/tess-weld.wgsl)
 * evaluates every point through one triangle, and the other side's triangles interpolate that
 * side's normal: a saw-tooth band of wrong shading along the crease in adaptive mode, where the
 * rows next to a crease are coarse (seen in the demo on the sheet's fold and in the gear's axle
 * hole, 2026-11-27).
 *
 * src/gpu/prepare.ts splitCreases outputs the points of such an edge once per side and a vertex
 * once per sector (both copies at the owner side's position, so the mesh stays watertight in
 * positions), but only where both ends of the edge are regular vertices (see there why).
 * Measured here, on the project models with such a crease: of the output triangles with a
 * vertex on it (a point of a sharp edge, or a vertex where two sharp edges meet or with a sharp
 * corner tag), those where such a vertex's normal is more than 45° from the triangle's geometric
 * normal, at fixed factors 4 and 16 (of the touching triangles in brackets):
 *
 *   model        no split                      split where regular   split everywhere (tried)
 *   creased box  68 / 260   (126 / 510)        68 / 260              20 / 20
 *   gear         425 / 1625 (815 / 3215)       425 / 1625            0 / 0
 *   pawn         128 / 512  (240 / 1008)       128 / 512             63 / 63
 *   sheet        47 / 191   (98 / 386)         0 / 0                 0 / 0
 *
 * (the worst were 78° off on the sheet, 90° on the pawn and gear, 167° on the box). Only crease
 * points are counted because a strongly curved smooth region passes 45° too: the creature,
 * which has no crease, has 82 such triangles at factor 4 and 67 at 16.
 *
 * NOT MET on the box, the gear and the pawn, whose sharp rims end at extraordinary vertices
 * (valence 3, or next to an n-gon). Splitting everywhere was tried: it mends the gear, but at the
 * pawn's rim vertices and the box's bottom corners the evaluator gives the vertex one limit
 * normal, whose tangents describe one sector (wgsl/surface-cc.wgsl ccSector at the vertex and in
 * its last square's radial blend; OpenSubdiv's convention, notes catmull-clark.md §2.2-2.3), so
 * the other sector had the right normal along its edge and the wrong one at the corner: a dark
 * spot at each rim vertex, which e2e/artifacts.spec.ts caught on the pawn (3 speckle pixels at
 * factor 8). The mend is a limit normal per sector in the fans' limit data (src/gpu/cc/build.ts
 * "fan limits"); then the regularity condition can go. The counts are held to their present size.
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
import { decodeBary } from '../src/gpu/contract.ts';
import type { Cage } from '../src/mesh/types.ts';
import type { PreparedMesh } from '../src/gpu/prepare.ts';
import { SHARPNESS_INFINITE } from '../src/mesh/types.ts';

const MODELS = new URL('../public/models/', import.meta.url);

/** Crease triangles with a wrong-side normal at factors 4 and 16, as measured on 2026-11-27 with
 * the split (see the header). */
const MEASURED: Record<string, [number, number]> = {
  'brick-box.obj': [68, 260],
  'creased-box.obj': [68, 260],
  'gear.obj': [425, 1625],
  'pawn.obj': [128, 512],
  'sheet.obj': [0, 0],
};

/** Which output vertices lie on an infinitely sharp crease, from each vertex's source triangle
 * and weights (so whatever the output's vertex order): a point with two nonzero weights on such
 * an edge, or a cage vertex where two or more such edges meet or whose corner tag is infinitely
 * sharp (one such edge ending there is a dart: one normal). */
function creasePoints(cage: Cage, mesh: PreparedMesh, out: MeshReadback): (v: number) => boolean {
  const key = (a: number, b: number) => (a < b ? `${a},${b}` : `${b},${a}`);
  const sharp = new Set(cage.creases.filter((c) => c.sharpness >= SHARPNESS_INFINITE).map((c) => key(c.v0, c.v1)));
  const incident = new Uint32Array(mesh.vertexCount);
  for (let e = 0; e < mesh.edgeCount; e++)
    if (sharp.has(key(mesh.edgeVerts[2 * e], mesh.edgeVerts[2 * e + 1])))
      for (const v of [mesh.edgeVerts[2 * e], mesh.edgeVerts[2 * e + 1]]) incident[v]++;
  const cornerTag = new Set(cage.corners.filter((c) => c.sharpness >= SHARPNESS_INFINITE).map((c) => c.v));
  return (v) => {
    const t = out.srcTri[v];
    if (t >= mesh.triangleCount) return false;
    const w = decodeBary(out.bary[v]);
    const on = [0, 1, 2].filter((i) => w[i] !== 0).map((i) => mesh.triVerts[3 * t + i]);
    if (on.length === 1) return incident[on[0]] >= 2 || cornerTag.has(on[0]);
    return on.length === 2 && sharp.has(key(on[0], on[1]));
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
        const m = wrongSide(r.out, creasePoints(cage, mesh, r.out));
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
