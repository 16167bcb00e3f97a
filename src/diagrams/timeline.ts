/**
 * Time → factor. A figure's factors are TRACKS: one value (static) or key values a..b..c that the
 * animation visits at equal steps of its phase s ∈ [0, 1]. Time t (seconds) maps to s by the loop
 * mode: ping-pong (up, hold, down, hold), repeat (up, hold, jump back) or once. Pure functions:
 * the same (params, t) always draws the same frame.
 */

export type Track = readonly number[];
export type LoopMode = 'pingpong' | 'repeat' | 'once';
export type Ease = 'linear' | 'log';

export interface Timing {
  /** Seconds for one sweep s: 0 → 1. */
  duration: number;
  /** Seconds held at each end. */
  hold: number;
  loop: LoopMode;
}

export function isAnimated(track: Track): boolean {
  return track.some((v) => v !== track[0]);
}

/** One cycle of the animation in seconds (the scrub range; `once` has no hold at the end). */
export function period(tm: Timing): number {
  if (tm.loop === 'pingpong') return 2 * (tm.duration + tm.hold);
  if (tm.loop === 'repeat') return tm.duration + tm.hold;
  return tm.duration;
}

const mod = (a: number, n: number) => ((a % n) + n) % n;

/** The phase s ∈ [0, 1] at time t. */
export function phaseAt(tm: Timing, t: number): number {
  const D = tm.duration;
  const H = tm.hold;
  if (!(D > 0)) return 0;
  if (tm.loop === 'once') return Math.min(1, Math.max(0, t / D));
  if (tm.loop === 'repeat') return Math.min(1, mod(t, D + H) / D);
  const p = mod(t, 2 * (D + H));
  if (p < D) return p / D;
  if (p < D + H) return 1;
  if (p < 2 * D + H) return 1 - (p - D - H) / D;
  return 0;
}

/** The value of a track at phase s (log ease interpolates geometrically between positive keys). */
export function trackValue(track: Track, s: number, ease: Ease): number {
  const n = track.length;
  if (n === 1) return track[0];
  let x = Math.min(1, Math.max(0, s)) * (n - 1);
  if (Math.abs(x - Math.round(x)) < 1e-9) x = Math.round(x); // land exactly on the keys
  const i = Math.min(Math.floor(x), n - 2);
  const f = x - i;
  const a = track[i];
  const b = track[i + 1];
  if (f === 0) return a;
  if (f === 1) return b;
  if (ease === 'log' && a > 0 && b > 0) return a * (b / a) ** f;
  return a + (b - a) * f;
}

/** Snap to whole factors (the "one at a time" figures step through integers). */
export function snapValue(v: number): number {
  return Math.floor(v + 1e-9);
}

/** A sensible sweep length for these tracks: about 1.5 s per octave (log) or 0.6 s per unit of
 * factor (linear), per key step, between 2 and 16 seconds. */
export function defaultDuration(tracks: readonly Track[], ease: Ease): number {
  let worst = 0;
  for (const tr of tracks) {
    let sum = 0;
    for (let i = 0; i + 1 < tr.length; i++) {
      const a = tr[i];
      const b = tr[i + 1];
      const cost = ease === 'log' && a > 0 && b > 0 ? 1.5 * Math.abs(Math.log2(b / a)) : 0.6 * Math.abs(b - a);
      sum += a === b ? 0.6 : Math.max(0.8, cost);
    }
    worst = Math.max(worst, sum);
  }
  return Math.round(Math.min(16, Math.max(2, worst)) * 10) / 10;
}

/** Smallest time t ≥ 0 on the first rising sweep where a two-key track reaches `value` (for
 * "start at factor 10.3"); null if the value is outside the track. */
export function timeForValue(track: Track, value: number, ease: Ease, tm: Timing): number | null {
  if (track.length !== 2) return null;
  const [a, b] = track;
  if (a === b || (value - a) * (value - b) > 0) return null;
  const s = ease === 'log' && a > 0 && b > 0 && value > 0 ? Math.log(value / a) / Math.log(b / a) : (value - a) / (b - a);
  return s * tm.duration;
}
