// The exact surface's normal at a crease vertex whose sector on one side is a single face (θ = π:
// the face's two edges there leave in opposite directions; src/subdiv/limit.ts vertexLimit): the
// normal approached along the face's diagonal, the GPU fans' convention. Before, OpenSubdiv's
// single-face mask gave it either sign (60 such corners of the gear with infinitely sharp rims had
// none defined, and where the rim is concave it pointed inward).
import { describe, expect, it } from 'vitest';
import { type Cage, SHARPNESS_INFINITE, loadCage } from '../../src/mesh/index.ts';
import { Surface, cageOptions, refineCage } from '../../src/subdiv/index.ts';
import gear from '../../public/models/gear.obj?raw';

const sharp = <T extends { sharpness: number }>(tags: T[]) =>
  tags.filter((t) => t.sharpness >= 1).map((t) => ({ ...t, sharpness: SHARPNESS_INFINITE }));

describe('a crease sector of one face', () => {
  it('the gear with infinitely sharp rims, after one step: every face corner has a normal, within 1° of the face’s just inside', () => {
    const raw = loadCage(gear).cage;
    const cage: Cage = refineCage({ ...raw, creases: sharp(raw.creases), corners: sharp(raw.corners) }).cage;
    const S = new Surface(cage, undefined, cageOptions(cage));
    const corners: [number, number, number, number][] = [
      [0, 0, 0.01, 0.01],
      [1, 0, 0.99, 0.01],
      [1, 1, 0.99, 0.99],
      [0, 1, 0.01, 0.99],
    ];
    let worst = 0;
    for (let f = 0; f < cage.faceOffsets.length - 1; f++)
      for (const [u, v, ui, vi] of corners) {
        const at = S.evaluate(f, u, v);
        expect(at.normalDefined, `face ${f} (${u}, ${v})`).toBe(true);
        const inside = S.evaluate(f, ui, vi).N;
        const cos = at.N[0] * inside[0] + at.N[1] * inside[1] + at.N[2] * inside[2];
        worst = Math.max(worst, (Math.acos(Math.min(1, cos)) * 180) / Math.PI);
      }
    expect(worst).toBeLessThan(1);
  });
});
