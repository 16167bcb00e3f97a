// The ACC schemes' normal at a patch corner where the patch has none of its own (the two tangents
// parallel: the corner of a crease sector of one face, as on the gear's rims after its Catmull-Clark
// step, and the creased box's cube corners): it is the patch's own approached from
// inside (src/subdiv/acc-evaluate.ts AccSurface.evaluate; wgsl/acc/surface.wgsl evalAccPatch
// the same). Held here against the exact limit surface of the same crease model (every tag of
// sharpness ≥ 1 infinitely sharp, as the schemes build them), evaluated just inside the face: before,
// the normal there was zero (Bezier, Pm) or the direction of rounding noise, up to 180° off.
import { describe, expect, it } from 'vitest';
import { type Cage, SHARPNESS_INFINITE, loadCage } from '../../src/mesh/index.ts';
import { ACC_SCHEMES, ACC_SHARP_FROM, accCage } from '../../src/subdiv/acc.ts';
import { AccSurface, evalPatchPoints } from '../../src/subdiv/acc-evaluate.ts';
import { Surface, cageOptions } from '../../src/subdiv/index.ts';
import gear from '../../public/models/gear.obj?raw';
import creasedBox from '../../public/models/creased-box.obj?raw';
import pawn from '../../public/models/pawn.obj?raw';

const dot = (a: readonly number[], b: readonly number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const degrees = (a: readonly number[], b: readonly number[]) =>
  (Math.acos(Math.max(-1, Math.min(1, dot(a, b) / Math.sqrt(dot(a, a) * dot(b, b))))) * 180) / Math.PI;

/** The cage as the ACC schemes model it: tags of sharpness ≥ 1 infinitely sharp, the rest smooth. */
function asBuilt(cage: Cage): Cage {
  const sharp = <T extends { sharpness: number }>(tags: T[]) =>
    tags.filter((t) => t.sharpness >= ACC_SHARP_FROM).map((t) => ({ ...t, sharpness: SHARPNESS_INFINITE }));
  return { ...cage, creases: sharp(cage.creases), corners: sharp(cage.corners) };
}

/** Inside each (u, v) corner of a quad, and each barycentric corner of a triangle. */
const QUAD: [number, number, number, number][] = [
  [0, 0, 0.01, 0.01],
  [1, 0, 0.99, 0.01],
  [1, 1, 0.99, 0.99],
  [0, 1, 0.01, 0.99],
];

describe('ACC normals where a patch corner has no tangent plane', () => {
  for (const [name, text, least] of [
    ['gear (refined once)', gear, 60],
    ['creased box', creasedBox, 5],
    ['pawn', pawn, 16],
  ] as const) {
    it(`${name}: a unit normal within 3° of the exact limit's just inside the face, every scheme`, () => {
      // The crease model the schemes build without their steps for semi-sharp tags (accCage would
      // decay those away): infinitely sharp from 1 on; n-gons refined once.
      const cage = accCage(asBuilt(loadCage(text).cage)).cage;
      const exact = new Surface(cage, undefined, cageOptions(cage));
      for (const scheme of ACC_SCHEMES) {
        const acc = new AccSurface(cage, scheme);
        let degenerate = 0;
        let worst = 0;
        for (let f = 0; f < acc.topology.nPatches; f++) {
          if (acc.topology.faceSize[f] !== 4) continue;
          for (const [u, v, ui, vi] of QUAD) {
            const r = evalPatchPoints(acc.kind(f), acc.patch(f), u, v);
            const [a, b] = r.tangents;
            if (dot(r.n, r.n) > 1e-8 * dot(a, a) * dot(b, b)) continue;
            degenerate++;
            const N = acc.evaluate(f, u, v).N;
            expect(Math.hypot(...N), `${scheme} face ${f} at (${u}, ${v})`).toBeCloseTo(1, 12);
            worst = Math.max(worst, degrees(N, exact.evaluate(f, ui, vi).N));
          }
        }
        console.log(`${scheme} ${name}: ${degenerate} corners without a tangent plane, worst ${worst.toFixed(2)}°`);
        expect(degenerate, scheme).toBeGreaterThanOrEqual(least);
        expect(worst, scheme).toBeLessThan(3);
      }
    });
  }
});
