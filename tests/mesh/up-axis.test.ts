import { describe, expect, it } from 'vitest';
import { makeCage, turnUpAxis } from '../../src/mesh/index.ts';

describe('turnUpAxis', () => {
  const cage = makeCage([1, 2, 3, 0, -4, 0, 0.1, 0, -0.7], [[0, 1, 2]]);
  it('Z-up to Y-up is (x, y, z) -> (x, z, -y), and Y-up to Z-up undoes it exactly, with no -0', () => {
    const up = turnUpAxis(cage, 'y-up');
    expect([...up.positions]).toEqual([1, 3, -2, 0, 0, 4, 0.1, -0.7, 0]);
    expect([...up.positions].some((x) => Object.is(x, -0))).toBe(false);
    const back = turnUpAxis(up, 'z-up');
    expect([...back.positions]).toEqual([...cage.positions]);
    expect([...back.positions].some((x) => Object.is(x, -0))).toBe(false);
    expect(back.faceIndices).toBe(cage.faceIndices);
  });
});
