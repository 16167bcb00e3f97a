/**
 * Every 1D line pattern of the talk behind one signature: `line(mode, factor)` → sorted
 * fixed-point points, 0 first and ONE last (see types.ts).
 *
 * - `pow2-snap`: subdivide at powers of two only. Pops at every power of two.
 * - `one-at-a-time`: the stable line: points k/N stay, the new points of an octave slide in
 *   one after another from their left neighbour (the talk's "sliding pivot"; lopsided).
 * - `even`: the 10.3 example: ⌊f⌋ segments of weight 1 and one sliding segment of weight
 *   frac(f) at the end, all divided by f. Every point moves; exact at integers.
 * - `odd-first`: one-at-a-time with odd points inserted before even ones.
 * - `slow-slide`: odd-first with several points sliding together, slowly.
 * - `hable`: slow-slide plus the clean 1 → 2 transition: Hable's final pattern.
 * - `integer`, `pow2`, `fractional_odd`, `fractional_even`: the D3D11 reference (d3d11.ts).
 *
 * Factors for the talk's modes are clamped to [1, maxFactor] (NaN → 1); the D3D11 modes clamp
 * and cull exactly as the reference does.
 */
import { ONE } from './fixed.ts';
import { MAX_FACTOR } from './max-factor.ts';
import { d3d11Line } from './d3d11.ts';
import { HABLE_OPTIONS, cachedSlots, stableFactorFixed, stableLineFixed, type StableLineOptions } from './hable-line.ts';
import type { LineMode, LinePattern } from './types.ts';
import { D3D11_PARTITIONINGS, type D3D11Partitioning } from './types.ts';

export const STABLE_VARIANTS: Record<'one-at-a-time' | 'odd-first' | 'slow-slide' | 'hable', StableLineOptions> = {
  'one-at-a-time': { order: 'left-to-right', overlap: 1, clean12: false },
  'odd-first': { order: 'odd-first', overlap: 1, clean12: false },
  'slow-slide': { order: 'odd-first', overlap: HABLE_OPTIONS.overlap, clean12: false },
  hable: HABLE_OPTIONS,
};

export function isD3D11Mode(mode: string): mode is D3D11Partitioning {
  return (D3D11_PARTITIONINGS as readonly string[]).includes(mode);
}

function pow2Snap(factor: number, maxFactor: number): LinePattern {
  const F = stableFactorFixed(factor, maxFactor);
  let n = 1;
  while (n * 2 * ONE <= F) n *= 2;
  const x: number[] = [];
  const moving: boolean[] = [];
  for (let k = 0; k <= n; k++) {
    x.push((k * ONE) / n);
    moving.push(n > 1 && k % 2 === 1); // the points the last power of two added
  }
  return { x, moving };
}

function even(factor: number, maxFactor: number): LinePattern {
  const F = stableFactorFixed(factor, maxFactor);
  const whole = Math.floor(F / ONE);
  const x: number[] = [];
  const moving: boolean[] = [];
  const fractional = F % ONE !== 0;
  for (let i = 0; i <= whole; i++) {
    // i/f in fixed point: i·2^32 / F, floored (exact in doubles: numerator < 2^41).
    x.push(Math.floor((i * ONE * ONE) / F));
    moving.push(fractional && i > 0);
  }
  if (fractional) {
    x.push(ONE);
    moving.push(false);
  }
  return { x, moving };
}

export interface LineOptions {
  /** Largest factor of the talk's modes (a power of two, 2..256). Default MAX_FACTOR (128). */
  maxFactor?: number;
}

export function line(mode: LineMode, factor: number, opts: LineOptions = {}): LinePattern {
  const maxFactor = opts.maxFactor ?? MAX_FACTOR;
  switch (mode) {
    case 'pow2-snap':
      return pow2Snap(factor, maxFactor);
    case 'even':
      return even(factor, maxFactor);
    case 'one-at-a-time':
    case 'odd-first':
    case 'slow-slide':
    case 'hable':
      return stableLineFixed(cachedSlots(maxFactor, STABLE_VARIANTS[mode]), stableFactorFixed(factor, maxFactor));
    default:
      if (isD3D11Mode(mode)) return d3d11Line(mode, factor);
      throw new RangeError(`unknown line mode '${String(mode)}'`);
  }
}

/** The points of a line walked in the other direction: ONE − x, still sorted ascending. */
export function reversed(p: LinePattern): LinePattern {
  return { x: p.x.map((v) => ONE - v).reverse(), moving: [...p.moving].reverse() };
}
