// One Catmull-Clark step of a whole cage as a new cage (src/subdiv/refine-cage.ts): its limit
// surface is the cage's. Every child face is evaluated at random (s, t) and compared with the cage's
// surface at the same point (a quad's quadrant; an n-gon's or triangle's sub-face), f64 to 1e-12 of
// the cage's size, on cages with semi-sharp and infinitely sharp creases, corners, boundaries,
// holes, n-gons and Chaikin creasing; and the new cage's uvs interpolate the cage's.
import { describe, expect, it } from 'vitest';
import { type Cage, cageDiagonal, loadCage, makeCage, uvAtSubFace } from '../../src/mesh/index.ts';
import { Surface, cageOptions, hasNgons, refineCage } from '../../src/subdiv/index.ts';
import { cube, grid3, pentPrism, triPrism } from '../support/subdiv-fixtures.ts';
import gear from '../../public/models/gear.obj?raw';
import pawn from '../../public/models/pawn.obj?raw';
import creasedBox from '../../public/models/creased-box.obj?raw';
import sheet from '../../public/models/sheet.obj?raw';
import brickBox from '../../public/models/brick-box.obj?raw';

function rng(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

const QUAD_CORNER: [number, number][] = [
  [0, 0],
  [1, 0],
  [1, 1],
  [0, 1],
];

/** The cage's (u, v) of the point (s, t) of child j of a cage quad. */
function quadParam(j: number, s: number, t: number): [number, number] {
  const c = QUAD_CORNER[j],
    next = QUAD_CORNER[(j + 1) % 4],
    prev = QUAD_CORNER[(j + 3) % 4];
  return [0, 1].map((i) => c[i] + (s * (next[i] - c[i])) / 2 + (t * (prev[i] - c[i])) / 2) as [number, number];
}

const chaikinCube = (): Cage => {
  const c = cube({
    creases: [
      [4, 5, 2.5],
      [5, 6, 1.25],
      [6, 7, 3],
      [0, 4, 0.5],
    ],
    corners: [[2, 1.5]],
  });
  c.fileOptions = { creasing: 'chaikin' };
  return c;
};

const cages: Record<string, () => Cage> = {
  'cube, semi-sharp and infinite creases, a semi-sharp corner': () =>
    cube({
      creases: [
        [4, 5, 2.3],
        [5, 6, 10],
        [1, 2, 0.6],
      ],
      corners: [[0, 1.5]],
    }),
  'cube, Chaikin creasing': chaikinCube,
  'cube with a hole': () => cube({ holes: [2] }),
  'pentagonal prism': pentPrism,
  'triangular prism': triPrism,
  'grid (boundary, corners)': grid3,
  gear: () => loadCage(gear).cage,
  pawn: () => loadCage(pawn).cage,
  'creased box': () => loadCage(creasedBox).cage,
  sheet: () => loadCage(sheet).cage,
};

describe('refineCage: one Catmull-Clark step as a cage', () => {
  for (const [name, make] of Object.entries(cages)) {
    it(`${name}: every child face's limit is the cage's, to 1e-12 of its size`, () => {
      const cage = make();
      const options = cageOptions(cage);
      const { cage: child, faceParent, faceCorner } = refineCage(cage);
      expect(hasNgons(child)).toBe(false);
      const S = new Surface(cage, undefined, options);
      const C = new Surface(child, undefined, cageOptions(child));
      const tol = 1e-12 * cageDiagonal(cage.positions);
      const r = rng(7);
      let compared = 0;
      for (let h = 0; h < child.faceOffsets.length - 1; h++) {
        const f = faceParent[h],
          j = faceCorner[h];
        expect(C.hasLimitSurface(h)).toBe(S.hasLimitSurface(f));
        if (!S.hasLimitSurface(f)) continue;
        for (let i = 0; i < 3; i++) {
          const s = r(),
            t = r();
          const got = C.evaluate(h, s, t);
          const want = S.faceSize(f) === 4 ? S.evaluate(f, ...quadParam(j, s, t)) : S.evaluateSubFace(f, j, s, t);
          for (let c = 0; c < 3; c++) expect(Math.abs(got.P[c] - want.P[c])).toBeLessThan(tol);
          compared++;
        }
      }
      expect(compared).toBeGreaterThan(0);
    });
  }

  it('the tags are those of level 1: halves of a crease decayed by one, Chaikin averaged, corners decayed', () => {
    const uniform = refineCage(cube({ creases: [[4, 5, 2.3]], corners: [[0, 1.5]] })).cage;
    expect(uniform.creases.map((c) => c.sharpness)).toEqual([Math.fround(1.3), Math.fround(1.3)]);
    expect(uniform.corners).toEqual([{ v: 0, sharpness: Math.fround(0.5), line: 0 }]);
    const chaikin = refineCage(chaikinCube()).cage;
    expect(chaikin.fileOptions.creasing).toBe('chaikin');
    // Under Chaikin the half of 4-5 at 5 averages with 5-6 (sharpness 1.25): not 1.5.
    expect(chaikin.creases.some((c) => c.sharpness > 1.5 - 1e-6 && c.sharpness < 1.5 + 1e-6 && c.v0 !== 4 && c.v1 !== 4)).toBe(false);
    expect(chaikin.creases.length).toBeGreaterThan(0);
  });

  it('uvs: each child corner carries the uv the cage face has there (linear all)', () => {
    const cage = loadCage(brickBox).cage;
    expect(cage.uvs.length).toBeGreaterThan(0);
    const { cage: child, faceParent, faceCorner } = refineCage(cage);
    const r = rng(3);
    for (let h = 0; h < child.faceOffsets.length - 1; h++) {
      const f = faceParent[h],
        j = faceCorner[h];
      const s = r(),
        t = r();
      const got = uvAtSubFace(child, h, 0, s, t).uv;
      const n = cage.faceOffsets[f + 1] - cage.faceOffsets[f];
      const want = n === 4 ? uvAtSubFace(cage, f, 0, ...quadParam(j, s, t)).uv : uvAtSubFace(cage, f, j, s, t).uv;
      expect(got[0]).toBeCloseTo(want[0], 12);
      expect(got[1]).toBeCloseTo(want[1], 12);
    }
  });

  it('a cage without uvs gives none; hasNgons tells pentagons from quads and triangles', () => {
    const c = makeCage([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], [[0, 1, 2, 3]]);
    const child = refineCage(c).cage;
    expect(child.uvs.length).toBe(0);
    expect([...child.faceUvIndices].every((i) => i === -1)).toBe(true);
    expect(hasNgons(pentPrism())).toBe(true);
    expect(hasNgons(triPrism())).toBe(false);
    expect(hasNgons(cube())).toBe(false);
  });
});
