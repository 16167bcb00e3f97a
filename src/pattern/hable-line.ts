/**
 * Hable's stable 1D line ("Part 1: The Triangle" of the talk) and the steps the talk takes to
 * reach it, as one slot schedule.
 *
 * A line is a list of SLOTS. A slot is a point that, once born, slides linearly from a start
 * position x0 to a final position x1 while the factor runs through a window [f0, f0 + w], and
 * then never moves again. Positions and factors are fixed point (fixed.ts): positions over 2^16,
 * factors as 16.16. The position of a slot at factor F is
 *
 *     x = x0 ± ceil(|x1 − x0| · clamp(F − f0, 0, w) / w)         (integer arithmetic)
 *
 * and |x1 − x0| · w + w < 2^32 for every slot (proved below), so the GPU computes the same value
 * with u32 arithmetic from the baked table. A slot is present while f0 < F < death. Rounding
 * away from the start means a present slot is never exactly on the point it was born from: it
 * leaves its parent by at least 2^-16 at once, so rows and columns of the triangle pattern never
 * coincide (except the two 1→2 points, which meet one unit of factor before the ghost dies).
 *
 * The schedule, for factors in [1, maxFactor] (maxFactor a power of two, 2..256):
 *  - 0 and 1 are always present.
 *  - Octave [1, 2]: with `clean12` (Hable's final pattern) two points come in from both ends
 *    and meet in the middle: one slides 0 → ½, a "ghost" slides 1 → ½ and dies at exactly
 *    F = 2, where it coincides with the first. Without `clean12` a single point slides 0 → ½.
 *  - Octave [N, 2N], N ≥ 2: the N points k/N never move; the N new points (2j+1)/(2N) are each
 *    born on their left neighbour j/N ("slide in from the previous point") and slide right.
 *    Order (`order`): left to right, or ODD BEFORE EVEN, recursively: rank(j) =
 *    bitreverse(N−1−j), which inserts the odd j first (the talk's "odd points before even for
 *    better balance"), and within each parity again the odd ones of the halved index first.
 *    Windows (`overlap` K): with K = 1 the points slide one after another, each in 1/N of the
 *    octave; with K > 1 each window is K times longer and consecutive windows overlap, so up to
 *    K points slide together, each K times slower (the talk's "slowly slide in multiple
 *    points"). Window r starts at N + r·N/(N+K−1) and ends at N + (r+K)·N/(N+K−1), so the last
 *    one ends exactly at 2N and every power of two is exactly uniform.
 *
 * Bound: a slot of octave N has |x1 − x0| = 2^16/(2N) and w ≤ N·2^16, so the product is ≤ 2^31,
 * and adding w − 1 for the ceiling stays below 2^32. (Octave 1: 2^15 · 2^16 = 2^31.)
 *
 * Choices the talk leaves open, made here: the slide starts on the LEFT neighbour; the order is
 * the recursive odd-first (bit-reversed) order; K = 4 for `hable`; slides are linear in the
 * factor (so the speed is constant inside a window; see the continuity constant in the tests).
 */
import { ONE, factorToFixed } from './fixed.ts';
import { MAX_FACTOR } from './max-factor.ts';
import type { LinePattern } from './types.ts';

export interface StableLineOptions {
  /** Insertion order inside an octave. */
  order: 'left-to-right' | 'odd-first';
  /** How many points slide at once (window length in units of the one-at-a-time window). */
  overlap: number;
  /** Two points from both ends on [1, 2] instead of one. */
  clean12: boolean;
}

export const HABLE_OPTIONS: StableLineOptions = { order: 'odd-first', overlap: 4, clean12: true };

export interface Slot {
  /** Start and final position, fixed point. */
  x0: number;
  x1: number;
  /** Slide window in 16.16 factor units: the slot is born (present) for F > f0 and reaches x1 at f0 + w. */
  f0: number;
  w: number;
  /** Present only while F < death (16.16); NO_DEATH for every slot but the 1→2 ghost. */
  death: number;
}

/** `f0` of the two static end points: present for every factor. */
export const ALWAYS = -1;
/** `death` of every slot that never dies (larger than any 16.16 factor up to 256). */
export const NO_DEATH = 0x7fffffff;

export const MAX_FACTOR_LIMIT = 256;

export function checkMaxFactor(maxFactor: number): void {
  if (!Number.isInteger(maxFactor) || maxFactor < 2 || maxFactor > MAX_FACTOR_LIMIT || (maxFactor & (maxFactor - 1)) !== 0) {
    throw new RangeError(`maxFactor must be a power of two in [2, ${MAX_FACTOR_LIMIT}], got ${maxFactor}`);
  }
}

function bitReverse(v: number, bits: number): number {
  let r = 0;
  for (let b = 0; b < bits; b++) r |= ((v >> b) & 1) << (bits - 1 - b);
  return r;
}

/**
 * Every slot that can ever be present up to maxFactor, sorted by final position (then start
 * position), which is also the order of their current positions at any factor.
 */
export function buildSlots(maxFactor: number, opt: StableLineOptions): Slot[] {
  checkMaxFactor(maxFactor);
  const slots: Slot[] = [
    { x0: 0, x1: 0, f0: ALWAYS, w: 1, death: NO_DEATH },
    { x0: ONE, x1: ONE, f0: ALWAYS, w: 1, death: NO_DEATH },
  ];
  const half = ONE / 2;
  slots.push({ x0: 0, x1: half, f0: ONE, w: ONE, death: NO_DEATH });
  if (opt.clean12) slots.push({ x0: ONE, x1: half, f0: ONE, w: ONE, death: 2 * ONE });
  const K = opt.overlap;
  for (let N = 2, n = 1; N < maxFactor; N *= 2, n++) {
    const denom = N + K - 1;
    for (let j = 0; j < N; j++) {
      const rank = opt.order === 'odd-first' ? bitReverse(N - 1 - j, n) : j;
      const start = Math.floor((rank * N * ONE) / denom);
      const end = Math.floor(((rank + K) * N * ONE) / denom);
      slots.push({
        x0: (j * ONE) / N,
        x1: ((2 * j + 1) * ONE) / (2 * N),
        f0: N * ONE + start,
        w: end - start,
        death: NO_DEATH,
      });
    }
  }
  slots.sort((a, b) => a.x1 - b.x1 || a.x0 - b.x0);
  return slots;
}

/** Whether a slot exists at 16.16 factor F. */
export function slotPresent(s: Slot, F: number): boolean {
  return s.f0 < F && F < s.death;
}

/** A slot's position at 16.16 factor F (integer arithmetic, exactly as the GPU does it). */
export function slotPosition(s: Slot, F: number): number {
  if (s.f0 === ALWAYS) return s.x1;
  const t = Math.min(Math.max(F - s.f0, 0), s.w);
  const span = Math.abs(s.x1 - s.x0);
  const d = Math.floor((span * t + s.w - 1) / s.w); // ceil; span·t + w − 1 < 2^32, exact as in u32
  return s.x1 >= s.x0 ? s.x0 + d : s.x0 - d;
}

/** Whether a present slot is still sliding at F (drawn red). */
export function slotMoving(s: Slot, F: number): boolean {
  return s.f0 !== ALWAYS && F < s.f0 + s.w;
}

/**
 * The 16.16 factor that the stable lines use: clamped to [1, maxFactor]; NaN and everything
 * below 1 (zero, negative) go to 1. The GPU pipeline never produces those, but a pattern
 * function must not crash on them.
 */
export function stableFactorFixed(factor: number, maxFactor: number): number {
  if (!(factor >= 1)) return ONE; // NaN, ≤ 1
  if (factor >= maxFactor) return maxFactor * ONE;
  return Math.min(Math.max(factorToFixed(factor), ONE), maxFactor * ONE);
}

const slotCache = new Map<string, Slot[]>();
export function cachedSlots(maxFactor: number, opt: StableLineOptions): Slot[] {
  const key = `${maxFactor}/${opt.order}/${opt.overlap}/${opt.clean12}`;
  let s = slotCache.get(key);
  if (!s) {
    s = buildSlots(maxFactor, opt);
    slotCache.set(key, s);
  }
  return s;
}

/** The present slots at F, in position order: what the baked "state" table stores. */
export function presentSlots(slots: Slot[], F: number): number[] {
  const out: number[] = [];
  for (let i = 0; i < slots.length; i++) if (slotPresent(slots[i], F)) out.push(i);
  return out;
}

/** A stable line at 16.16 factor F. */
export function stableLineFixed(slots: Slot[], F: number): LinePattern {
  const x: number[] = [];
  const moving: boolean[] = [];
  for (const s of slots) {
    if (!slotPresent(s, F)) continue;
    x.push(slotPosition(s, F));
    moving.push(slotMoving(s, F));
  }
  return { x, moving };
}

export function stableLine(factor: number, opt: StableLineOptions, maxFactor = MAX_FACTOR): LinePattern {
  return stableLineFixed(cachedSlots(maxFactor, opt), stableFactorFixed(factor, maxFactor));
}

/** Hable's final line pattern. */
export function hableLine(factor: number, maxFactor = MAX_FACTOR): LinePattern {
  return stableLine(factor, HABLE_OPTIONS, maxFactor);
}
