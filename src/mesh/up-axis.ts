/**
 * A cage turned a quarter turn about +X between the two up-axis conventions: Z-up to Y-up (OBJ's,
 * and how the project's models are stored) is (x, y, z) → (x, z, −y); Y-up to Z-up its inverse,
 * (x, y, z) → (x, −z, y). Exact in floating point (a coordinate is moved or negated, never
 * rounded; a 0 stays +0, not −0, so written files do not change).
 */
import type { Cage } from './types.ts';

export function turnUpAxis(cage: Cage, to: 'y-up' | 'z-up'): Cage {
  const p = cage.positions.slice();
  const neg = (x: number) => (x === 0 ? 0 : -x);
  for (let i = 0; i < p.length; i += 3) {
    const y = p[i + 1],
      z = p[i + 2];
    p[i + 1] = to === 'y-up' ? z : neg(z);
    p[i + 2] = to === 'y-up' ? neg(y) : y;
  }
  return { ...cage, positions: p };
}
