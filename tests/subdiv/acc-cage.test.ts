// The cage the ACC schemes take (src/subdiv/acc.ts accCage): one Catmull-Clark step for n-gons,
// ceil(σ) for semi-sharp creases (none left after them), within a step and patch budget; and what
// the steps buy: each scheme's distance from the exact limit surface at the same parameter, the
// error views' measure, before (σ rounded to 0 or ∞) and after (the exact refinement of σ).
import { describe, expect, it } from 'vitest';
import { cageDiagonal, loadCage, makeCage } from '../../src/mesh/index.ts';
import { ACC_MAX_STEPS, ACC_SCHEMES, accCage } from '../../src/subdiv/acc.ts';
import { AccSurface } from '../../src/subdiv/acc-evaluate.ts';
import { Surface, cageOptions } from '../../src/subdiv/index.ts';
import creasedBox from '../../public/models/creased-box.obj?raw';
import sheet from '../../public/models/sheet.obj?raw';
import icosphere from '../../public/models/icosphere.obj?raw';
import torus from '../../public/models/torus.obj?raw';
import { cube } from '../support/subdiv-fixtures.ts';

function rng(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

/** Max distance (÷ the cage's size) of a scheme's surface from the exact limit, at random quad parameters. */
function accError(cage: ReturnType<typeof loadCage>['cage'], scheme: (typeof ACC_SCHEMES)[number], samples = 600): number {
  const acc = new AccSurface(cage, scheme);
  const exact = new Surface(cage, undefined, cageOptions(cage));
  const r = rng(5);
  const size = cageDiagonal(cage.positions);
  let max = 0;
  const nf = cage.faceOffsets.length - 1;
  for (let i = 0; i < samples; i++) {
    const f = Math.floor(r() * nf);
    const u = r(),
      v = r();
    const a = acc.evaluate(f, u, v).P,
      e = exact.evaluate(f, u, v).P;
    max = Math.max(max, Math.hypot(a[0] - e[0], a[1] - e[1], a[2] - e[2]) / size);
  }
  return max;
}

describe('accCage', () => {
  it('a quad cage without semi-sharp tags is taken as it is', () => {
    const cage = loadCage(torus).cage;
    expect(accCage(cage)).toEqual({ cage, note: null, steps: 0 });
  });

  it('n-gons: one step; semi-sharp creases: ceil(σ) steps, none left after them; the same object for every call', () => {
    const ico = loadCage(icosphere).cage;
    expect(accCage(ico).note).toBe('one Catmull-Clark step first (the cage has n-gons): 230 patches');
    expect(accCage(ico).steps).toBe(1);
    const box = loadCage(creasedBox).cage; // σ up to 2.5
    const r = accCage(box);
    expect(r.cage.faceOffsets.length - 1).toBe(24 * 4 ** 3);
    expect(r.note).toBe('3 Catmull-Clark steps first (semi-sharp creases up to 2.5 decay): 1,536 patches');
    expect(r.steps).toBe(3);
    expect([...r.cage.creases, ...r.cage.corners].every((t) => t.sharpness === 0 || t.sharpness >= 10)).toBe(true);
    expect(accCage(box)).toBe(r);
  });

  it('at most ACC_MAX_STEPS steps: sharpness 9 keeps 5 of it (built sharp), and the note says so', () => {
    const r = accCage(cube({ creases: [[4, 5, 9]] }));
    expect(r.cage.faceOffsets.length - 1).toBe(6 * 4 ** ACC_MAX_STEPS);
    expect(r.steps).toBe(ACC_MAX_STEPS);
    expect(r.note).toMatch(/what is left of sharper creases is built sharp/);
    expect(Math.max(...r.cage.creases.map((c) => (c.sharpness < 10 ? c.sharpness : 0)))).toBeCloseTo(5, 5);
  });

  for (const [name, text] of [
    ['creased box', creasedBox],
    ['sheet', sheet],
  ] as const)
    it(`${name}: every scheme is closer to the exact limit after the steps (the error view's measure)`, () => {
      const cage = loadCage(text).cage;
      for (const scheme of ACC_SCHEMES) {
        const before = accError(cage, scheme);
        const after = accError(accCage(cage).cage, scheme);
        console.log(`${name} ${scheme}: max ${before.toExponential(2)} → ${after.toExponential(2)} of the size`);
        expect(after).toBeLessThan(before / 4);
      }
    });

  it('a budget-free pass-through for cages whose only tags are infinitely sharp', () => {
    const c = makeCage([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], [[0, 1, 2, 3]], { creases: [[0, 1, 10]] });
    expect(accCage(c).cage).toBe(c);
  });
});
