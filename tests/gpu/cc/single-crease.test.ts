/**
 * Single-crease patches in the topology-only Catmull-Clark preparation (src/gpu/cc/build.ts):
 * faces regular but for one semi-sharp crease along a side stop at depth 0 (no ceil(σ) levels),
 * and what they store (16 indices in a frame turned so the crease is its x = 0 side, σ) is, with
 * the f64 closed form of src/subdiv/crease-basis.ts, the exact limit surface (src/subdiv); so
 * is the closed-form limit of the cage vertices on such creases (wgsl/cc/build.wgsl vertexLimit).
 */
import { describe, it, expect } from 'vitest';
import { buildCatmullClark, rot, type CatmullClarkData } from '../../../src/gpu/cc/build.ts';
import { REGION_PATCH } from '../../../src/gpu/cc/regions.ts';
import { CC_REGION_WORD, CC_VERTEX_LIMIT_WORD } from '../../../src/gpu/cc/words.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { DEFAULT_OPTIONS, type Cage } from '../../../src/mesh/index.ts';
import { Surface } from '../../../src/subdiv/index.ts';
import { evalCreasePatch } from '../../../src/subdiv/crease-basis.ts';
import { cornerLimit, creasedGridCube } from '../../support/single-crease-fixture.ts';
import { cube, ringCrease } from '../../support/subdiv-fixtures.ts';

const f32 = (w: number) => new Float32Array(Uint32Array.of(w).buffer)[0];

function patchWords(cc: CatmullClarkData, w1: number, n: number): number[] {
  return Array.from(cc.words.subarray(cc.layout.offset.patchIdx + w1, cc.layout.offset.patchIdx + w1 + n));
}

function check(cage: Cage) {
  const cc = buildCatmullClark(cage, prepareMesh(cage));
  const S = new Surface(cage, undefined, { ...DEFAULT_OPTIONS, ...cage.fileOptions });
  let single = 0,
    maxErr = 0,
    maxErrN = 0;
  const seen = new Set<number>();
  let s = 3;
  const rnd = () => (s = (s * 16807) % 2147483647) / 2147483647;
  for (let f = 0; f < cage.faceOffsets.length - 1; f++) {
    if (cc.faceDepth[f] !== 0) continue;
    const w = CC_REGION_WORD.unpack(cc.regions[2 * cc.faceRegion[f]]);
    if (w.kind !== REGION_PATCH || !w.crease) continue;
    single++;
    expect(w.mask).toBe(0);
    const words = patchWords(cc, cc.regions[2 * cc.faceRegion[f] + 1], 17);
    const sigma = f32(words[16]);
    seen.add(sigma);
    // Depth 0: the indices are cage vertices.
    const cp = words.slice(0, 16).flatMap((p) => [cage.positions[3 * p], cage.positions[3 * p + 1], cage.positions[3 * p + 2]]);
    for (let i = 0; i < 12; i++) {
      // Dense near the crease (u → 0 in the patch frame), where the basis changes piece.
      const u = i < 4 ? [0, 1e-4, 0.3, 1][i] : rnd(),
        v = i < 4 ? rnd() : rnd();
      const [x, y] = rot(w.rot, u, v);
      const got = evalCreasePatch(cp, sigma, x, y);
      const ref = S.evaluate(f, u, v);
      maxErr = Math.max(maxErr, Math.hypot(got.P[0] - ref.P[0], got.P[1] - ref.P[1], got.P[2] - ref.P[2]));
      const dot = got.N[0] * ref.N[0] + got.N[1] * ref.N[1] + got.N[2] * ref.N[2];
      maxErrN = Math.max(maxErrN, 1 - dot);
    }
  }
  return { cc, S, single, maxErr, maxErrN, sigmas: [...seen].sort() };
}

describe('single-crease patches', () => {
  it('a cube of 6×6 grids with a σ = 2.7 and a σ = 0.5 crease loop: no ceil(σ) levels, patches exact', () => {
    const cage = creasedGridCube(6, [
      [2, 2.7],
      [4, 0.5],
    ]);
    const { cc, single, maxErr, maxErrN, sigmas } = check(cage);
    // Only the cube corners (valence 3) need a level; the creases none (ceil(2.7) = 3 before).
    expect(cc.levels).toBe(1);
    expect(cc.levels).toBeLessThan(Math.ceil(2.7));
    // Each loop has 24 edges and a single-crease patch on each side of each.
    expect(single).toBe(2 * 2 * 24);
    expect(cc.singleCreaseCount).toBe(single);
    expect(sigmas).toEqual([Math.fround(0.5), Math.fround(2.7)].sort());
    expect(maxErr).toBeLessThan(1e-12);
    expect(maxErrN).toBeLessThan(1e-12);
  });

  for (const sigma of [0.5, 1, 1.5, 2.7, 5, 9.5]) {
    it(`σ = ${sigma}: patches exact against the refinement reference`, () => {
      const { single, maxErr, maxErrN } = check(creasedGridCube(6, [[3, sigma]]));
      expect(single).toBe(48);
      expect(maxErr).toBeLessThan(1e-12);
      expect(maxErrN).toBeLessThan(1e-12);
    });
  }

  it('cage vertices on a straight semi-sharp crease: the closed-form limit (vertexLimit) is the exact one', () => {
    const cage = creasedGridCube(6, [
      [2, 2.7],
      [4, 0.5],
    ]);
    const cc = buildCatmullClark(cage, prepareMesh(cage));
    const S = new Surface(cage, undefined, { ...DEFAULT_OPTIONS, ...cage.fileOptions });
    const nV = cage.positions.length / 3;
    let n = 0;
    for (let v = 0; v < nV; v++) {
      const word = cc.words[cc.layout.offset.vertexFan + v];
      const { crease, index } = CC_VERTEX_LIMIT_WORD.unpack(word);
      if (!crease) continue;
      n++;
      const rec = patchWords(cc, index, 10);
      const sigma = f32(rec[9]);
      const k = Math.floor(sigma);
      const rho = 2 ** -k * (1 - 0.5 * (sigma - k));
      const wa = [rho / 6, 1 - rho / 3, rho / 6],
        wb = [1 / 6, 2 / 3, 1 / 6],
        d = [-0.5, 0, 0.5];
      const P = [0, 0, 0],
        Pa = [0, 0, 0],
        Pb = [0, 0, 0];
      for (let a = 0; a < 3; a++)
        for (let b = 0; b < 3; b++)
          for (let x = 0; x < 3; x++) {
            const q = cage.positions[3 * rec[3 * a + b] + x];
            P[x] += wa[a] * wb[b] * q;
            Pa[x] += d[a] * wb[b] * q;
            Pb[x] += wa[a] * d[b] * q;
          }
      const ref = cornerLimit(S, cage, v);
      expect(Math.hypot(P[0] - ref.P[0], P[1] - ref.P[1], P[2] - ref.P[2])).toBeLessThan(1e-12);
      // The normal: both sides of the crease agree for finite σ; oriented as the surface's.
      const N = [Pa[1] * Pb[2] - Pa[2] * Pb[1], Pa[2] * Pb[0] - Pa[0] * Pb[2], Pa[0] * Pb[1] - Pa[1] * Pb[0]];
      const l = Math.hypot(...N);
      expect(N[0] * ref.N[0] + N[1] * ref.N[1] + N[2] * ref.N[2]).toBeGreaterThan(l * (1 - 1e-9));
    }
    expect(n).toBe(2 * 24); // every vertex of both loops (on the cube's vertical edges too: valence 4)
  });

  it('the region word: kind and rot where the evaluator and regionOf read them, offset and sector where ccEvalRegion shifts them by hand', () => {
    const w = CC_REGION_WORD.pack({ kind: 2, rot: 3, mask: 0, offset: 9, sector: 37, crease: 1, patchKind: 3 });
    expect(w & 3).toBe(2);
    expect((w >> 2) & 3).toBe(3);
    expect((w >> 8) & 15).toBe(9);
    expect((w >> 12) & 63).toBe(37);
    expect((w >> 24) & 3).toBe(3);
    expect(CC_VERTEX_LIMIT_WORD.unpack(0xffffffff)).toEqual({ index: 0x7fffffff, crease: 1 }); // NONE stays NONE
  });

  it('a crease into an extraordinary vertex is no single crease: its fans take it (no ceil σ levels)', () => {
    const cc = buildCatmullClark(cube({ creases: ringCrease(2.5) }), prepareMesh(cube({ creases: ringCrease(2.5) })));
    expect(cc.levels).toBe(1);
    expect(cc.singleCreaseCount).toBe(0);
    expect(cc.semiAxes).toBe(true);
  });
});
