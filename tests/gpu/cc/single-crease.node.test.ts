/**
 * Single-crease patches on an OpenSubdiv regression cage (third-party, read from ../shared/cages,
 * never copied; skipped where it is absent): catmark_pawn's σ ≈ 5 crease loops all run straight
 * through valence-4 vertices, so the cage is prepared with 1 uniform level (6 before the
 * single-crease patches: 376 KB of GPU data per face, now ~0.5 KB), and its output vertices lie
 * on the exact limit (src/subdiv) within 1e-6 of the bounding-box diagonal, outside the blended
 * squares round extraordinary vertices.
 */
import { describe, it, expect, afterAll } from 'vitest';
import { existsSync, readFileSync } from 'node:fs';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { CCReference, exactTessellator, outputErrors, tessellateCC } from '../../support/cc-checks.ts';
import type { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { loadCage } from '../../../src/mesh/index.ts';

const FILE = '../shared/cages/catmark_pawn.obj';
const MAX_BOUND = 1e-6;
const SAMPLE = 3000;

let tess: Tessellator | undefined;
afterAll(() => {
  tess?.destroy();
  return releaseDevice();
});

describe.skipIf(!existsSync(FILE))('single-crease patches on catmark_pawn', () => {
  it('one uniform level, ≤ 1 KB per face, output vertices on the exact limit', async () => {
    const cage = loadCage(readFileSync(FILE, 'utf8')).cage;
    const mesh = prepareMesh(cage);
    const cc = buildCatmullClark(cage, mesh);
    const faces = cage.faceOffsets.length - 1;
    expect(cc.levels).toBe(1);
    expect(cc.singleCreaseCount).toBeGreaterThan(0);
    expect(cc.gpuBytes / faces).toBeLessThan(1024);
    const device = await getDevice();
    tess ??= exactTessellator(device);
    const out = await tessellateCC(device, tess, mesh, cc, testCamera(mesh, 1.5 * mesh.size, 3));
    const { errs, max, p99, nan, worst } = outputErrors(new CCReference(cage, mesh, cc), out, SAMPLE);
    console.log(
      'catmark_pawn',
      JSON.stringify({
        faces,
        levels: cc.levels,
        single: cc.singleCreaseCount,
        bytesPerFace: Math.round(cc.gpuBytes / faces),
        checked: errs.length,
        max,
        p99,
      }),
    );
    expect(nan).toBe(0);
    expect(max, worst).toBeLessThan(MAX_BOUND);
  });
});
