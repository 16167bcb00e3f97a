/**
 * Vertices of more faces than a workgroup has threads (the slice kernel's wide fans,
 * wgsl/cc/build.wgsl wideSlices: a workgroup of their own, whose threads take the sectors in turn
 * and read the step before from the stored slices). A disk of 100 quads round an interior vertex
 * (smooth), with two infinitely sharp edges through it (a crease) and with three (a corner), and
 * the half-disk whose centre is on the boundary (its pseudo-sector), and a semi-sharp crease
 * through it (decaying in the wide kernel): output vertices against the
 * exact CPU reference within 1e-6 of the diagonal, no NaN; and the fan is a wide one (its
 * thread words say so). Before, such vertices were refused ("faces round it").
 */
import { afterAll, describe, expect, it } from 'vitest';
import { getDevice, releaseDevice, testCamera } from '../../support/gpu-device.ts';
import { CCReference, exactTessellator, outputErrors, tessellateCC } from '../../support/cc-checks.ts';
import type { Tessellator } from '../../../src/gpu/tess/tessellator.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { buildCatmullClark } from '../../../src/gpu/cc/build.ts';
import { CC_THREAD_WORD, CC_WIDE_FAN } from '../../../src/gpu/cc/words.ts';
import { CC_NONE } from '../../../src/gpu/contract/cc.ts';
import { type Cage, makeCage } from '../../../src/mesh/index.ts';

const N = 100;

/** A disk (or, `half`, a half-disk) of N quads round vertex 0: rings of radius 1 and 2, gently domed. */
function pole(half: boolean, creases: [number, number, number][] = []): Cage {
  const pos = [0, 0, 0.6];
  const span = half ? Math.PI : 2 * Math.PI;
  const m = half ? N + 1 : N; // ring vertices
  for (let r = 1; r <= 2; r++)
    for (let i = 0; i < m; i++) {
      const a = (span * i) / N;
      pos.push(r * Math.cos(a), r * Math.sin(a), 0.6 - 0.25 * r * r + 0.05 * Math.sin(5 * a));
    }
  const ring = (r: number, i: number) => 1 + (r - 1) * m + (half ? i : i % N);
  // Quads round the centre (centre, inner i, outer i, inner i + 1), triangles between them outside.
  const faces: number[][] = [];
  for (let i = 0; i < N; i++) faces.push([0, ring(1, i), ring(2, i), ring(1, i + 1)]);
  for (let i = 0; i < N; i++) faces.push([ring(1, i + 1), ring(2, i), ring(2, i + 1)]);
  return makeCage(pos, faces, { creases });
}

let tess: Tessellator | undefined;
afterAll(() => {
  tess?.destroy();
  return releaseDevice();
});

describe('wide fans: a vertex of 100 faces', () => {
  // [name, cage, fixed factor]: the semi-sharp crease's fan starts at level 2 (the ring's
  // triangles), a sixteenth of a face round the centre, so its case samples at factor 32.
  const cases: [string, Cage, number?][] = [
    ['interior, smooth', pole(false)],
    [
      'interior, a crease through it',
      pole(false, [
        [0, 1, 10],
        [0, 1 + N / 2, 10],
      ]),
    ],
    [
      'interior, a corner of three sharp edges',
      pole(false, [
        [0, 1, 10],
        [0, 1 + Math.round(N / 3), 10],
        [0, 1 + Math.round((2 * N) / 3), 10],
      ]),
    ],
    ['on the boundary (a half-disk)', pole(true)],
    // Semi-sharp: the crease decays inside the wide kernel (its centre's rule from the fan's
    // step table, wgsl/cc/build.wgsl wideCentreMask); 3.5 at the cage, 1.5 at level 2 where the
    // fan starts, so its rule changes from crease to smooth in its second step, with W = 0.5.
    [
      'interior, a semi-sharp crease through it',
      pole(false, [
        [0, 1, 3.5],
        [0, 1 + N / 2, 3.5],
      ]),
      32,
    ],
  ];
  for (const [name, cage, factor = 4] of cases) {
    it(`${name}: the limit within 1e-6 of the diagonal, no NaN; a wide fan`, async () => {
      const device = await getDevice();
      tess ??= exactTessellator(device, 1 << 19);
      const mesh = prepareMesh(cage);
      const cc = buildCatmullClark(cage, mesh);
      const threads = cc.words.subarray(cc.layout.offset.threads, cc.layout.offset.threads + cc.layout.length.threads);
      const wide = [...threads].filter((w) => w !== CC_NONE && CC_THREAD_WORD.get(w, 'sector') === CC_WIDE_FAN);
      expect(wide.length, 'wide fans').toBeGreaterThan(0);
      const out = await tessellateCC(device, tess, mesh, cc, testCamera(mesh, 1.5 * mesh.size, factor));
      const { errs, max, nan } = outputErrors(new CCReference(cage, mesh, cc), out, 600);
      console.log(
        `${name}: ${wide.length} wide fan(s), ${out.triangleCount} triangles, checked ${errs.length}, max ${max.toExponential(2)}`,
      );
      expect(nan).toBe(0);
      expect(errs.length).toBeGreaterThan(100);
      expect(max).toBeLessThan(1e-6);
    }, 120_000);
  }
});
