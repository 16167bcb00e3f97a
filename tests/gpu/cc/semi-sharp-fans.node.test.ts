/**
 * Semi-sharp creases decaying inside the slice kernel, on OpenSubdiv's hard-surface regression
 * cages (third-party, read from ../shared/cages, never copied; skipped where it is absent):
 * the project's creased box (in the repository: σ 1.5 creases ending at the cube's corners, so
 * the centres' rules change between steps and the axes' points blend by W = 0.5 in the second),
 * catmark_car and catmark_bishop have σ ≈ 5-6 creases through extraordinary vertices and ending
 * at darts, catmark_rook σ 7.9 creases meeting at corners, catmark_helmet σ 7. Their centres
 * are fans at once (src/gpu/cc/fans.ts: the axes' sharpness decays a unit a step in
 * wgsl/cc/slices.wgsl sliceStep, the centre takes each step's rule from its table, the sub-patches
 * next to a still-sharp axis take the crease basis), so no uniform level is refined for them:
 * before, the car and the bishop took 6 levels of the whole cage (266 and 231 KB per face) and
 * sharpness above 6 was refused. Held: at most 2 levels, the issue's 4 KB per face on the car and
 * the bishop (8 KB on the others), and every sampled output vertex on the exact limit (src/subdiv,
 * itself equal to OpenSubdiv) within 1e-6 of the diagonal, p99 within 1e-7, outside the blended
 * squares round extraordinary vertices. The cages are moved to their centroid first (the limit
 * surface moves with the cage): the rook lies 3.2 units from the origin with a diagonal of 0.87,
 * where an f32 coordinate alone is off by up to 1.4e-7 of the diagonal (measured in place: p99
 * 2.9e-7, the bishop's 1.1e-7; centred 2.9e-8 and 2.5e-8), and that is the output format's
 * precision, not the kernel's.
 */
import { afterAll, describe, expect, it } from 'vitest';
import { existsSync, readFileSync } from 'node:fs';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { CCReference, exactTessellator, outputErrors, tessellateCC } from '../../support/cc-checks.ts';
import type { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { type Cage, loadCage } from '../../../src/mesh/index.ts';

const DIR = '../shared/cages';
const MODELS = 'public/models';
const MAX_BOUND = 1e-6;
const P99_BOUND = 1e-7;
const SAMPLE = 2000;
/** Bytes of GPU subdivision data per cage face each cage is held to. */
const OWN = { 'creased-box': 8192 };
const CAGES: Record<string, number> = { ...OWN, catmark_car: 4096, catmark_bishop: 4096, catmark_rook: 8192, catmark_helmet: 8192 };

/** The cage moved so that its vertices' centroid is the origin. */
function centred(cage: Cage): Cage {
  const p = cage.positions;
  const n = p.length / 3;
  for (let k = 0; k < 3; k++) {
    let s = 0;
    for (let i = 0; i < n; i++) s += p[3 * i + k];
    for (let i = 0; i < n; i++) p[3 * i + k] -= s / n;
  }
  return cage;
}

let tess: Tessellator | undefined;
afterAll(() => {
  tess?.destroy();
  return releaseDevice();
});

describe('semi-sharp creases decaying inside the slice kernel', () => {
  for (const [name, bound] of Object.entries(CAGES)) {
    const file = name in OWN ? `${MODELS}/${name}.obj` : `${DIR}/${name}.obj`;
    it.skipIf(!existsSync(file))(
      `${name}: no more than 2 levels, ≤ ${bound} B per face, output on the exact limit`,
      async () => {
        const cage = centred(loadCage(readFileSync(file, 'utf8')).cage);
        const mesh = prepareMesh(cage);
        const cc = buildCatmullClark(cage, mesh);
        const faces = cage.faceOffsets.length - 1;
        expect(cc.semiAxes).toBe(true);
        expect(cc.levels).toBeLessThanOrEqual(2);
        expect(cc.gpuBytes / faces).toBeLessThanOrEqual(bound);
        const device = await getDevice();
        tess ??= exactTessellator(device);
        const out = await tessellateCC(device, tess, mesh, cc, testCamera(mesh, 1.5 * mesh.size, 3));
        const { errs, max, p99, nan, worst } = outputErrors(new CCReference(cage, mesh, cc), out, SAMPLE);
        console.log(
          name,
          JSON.stringify({ faces, levels: cc.levels, bytesPerFace: Math.round(cc.gpuBytes / faces), checked: errs.length, max, p99 }),
        );
        expect(nan).toBe(0);
        expect(errs.length).toBeGreaterThan(300);
        expect(max, worst).toBeLessThan(MAX_BOUND);
        expect(p99).toBeLessThan(P99_BOUND);
      },
      120_000,
    );
  }
});
