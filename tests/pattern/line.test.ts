import { MAX_FACTOR } from '../../src/pattern/max-factor.ts';
import { describe, it, expect } from 'vitest';
import fc from 'fast-check';
import { ONE, factorToFixed } from '../../src/pattern/fixed.ts';
import { line, reversed } from '../../src/pattern/line.ts';
import { buildSlots, cachedSlots, HABLE_OPTIONS, slotPosition, stableFactorFixed } from '../../src/pattern/hable-line.ts';
import { LINE_MODES, type LineMode } from '../../src/pattern/types.ts';
import { hausdorffSorted } from '../support/pattern-helpers.ts';

const TALK_MODES = ['pow2-snap', 'one-at-a-time', 'even', 'odd-first', 'slow-slide', 'hable'] as const;
const CONTINUOUS: LineMode[] = ['one-at-a-time', 'even', 'odd-first', 'slow-slide', 'hable', 'fractional_odd', 'fractional_even'];
const factor = fc.double({ min: 1, max: 64, noNaN: true });

describe('every line mode', () => {
  it('is sorted, starts at 0 and ends at ONE', () => {
    fc.assert(
      fc.property(fc.constantFrom(...LINE_MODES), factor, (mode, f) => {
        const { x, moving } = line(mode, f);
        expect(x.length).toBeGreaterThanOrEqual(2);
        expect(moving.length).toBe(x.length);
        expect(x[0]).toBe(0);
        expect(x[x.length - 1]).toBe(ONE);
        // The D3D11 reference itself is not sorted for fractional_even just above 6 and 30
        // (its rounded-up reciprocals put the point before the midpoint past ½; see d3d11.ts).
        const F = factorToFixed(f);
        const refUnsorted = mode === 'fractional_even' && ((F > 6 * ONE && F <= 6 * ONE + 6) || (F > 30 * ONE && F <= 30 * ONE + 414));
        if (!refUnsorted) for (let i = 1; i < x.length; i++) expect(x[i]).toBeGreaterThanOrEqual(x[i - 1]);
        for (const v of x) expect(Number.isInteger(v)).toBe(true);
      }),
      { numRuns: 3000 },
    );
  });

  it('has the documented point count', () => {
    fc.assert(
      fc.property(factor, (f) => {
        const F = factorToFixed(f) / ONE;
        expect(line('pow2-snap', f).x.length).toBe(2 ** Math.floor(Math.log2(F)) + 1);
        expect(line('even', f).x.length).toBe(Math.floor(F) + (Number.isInteger(F) ? 1 : 2));
        // The stable lines have between N+1 and 2N+1 points in octave [N, 2N].
        const N = 2 ** Math.floor(Math.log2(F));
        for (const mode of ['one-at-a-time', 'odd-first', 'slow-slide', 'hable'] as const) {
          const n = line(mode, f).x.length;
          if (N === 1 && mode === 'hable') expect([2, 4]).toContain(n);
          else {
            expect(n).toBeGreaterThanOrEqual(N + 1);
            expect(n).toBeLessThanOrEqual(2 * N + 1);
          }
        }
      }),
      { numRuns: 2000 },
    );
  });

  it('clamps out-of-range factors instead of failing', () => {
    for (const mode of TALK_MODES) {
      for (const f of [NaN, -3, 0, 0.5]) expect(line(mode, f)).toEqual(line(mode, 1));
      for (const f of [MAX_FACTOR, MAX_FACTOR + 1, 1e9, Infinity]) expect(line(mode, f)).toEqual(line(mode, MAX_FACTOR));
    }
  });
});

describe('continuity (no popping)', () => {
  // Sweep the factor over [1, 64] in steps of 1e-3: the Hausdorff distance between consecutive
  // point sets (in units of the edge) must stay below C·1e-3. C is printed per mode.
  const step = 1e-3;
  for (const mode of CONTINUOUS) {
    it(`${mode} moves every point continuously`, () => {
      let prev = line(mode, 1).x;
      let worst = 0;
      let worstAbove2 = 0; // past the 1 → 2 octave, where the slow slide shows
      for (let i = 1; i <= 63_000; i++) {
        const cur = line(mode, 1 + i * step).x;
        const d = hausdorffSorted(prev, cur) / ONE;
        worst = Math.max(worst, d);
        if (i > 1000) worstAbove2 = Math.max(worstAbove2, d);
        prev = cur;
      }
      const C = worst / step;
      console.log(`continuity constant C(${mode}) = ${C.toFixed(3)} (factors above 2: ${(worstAbove2 / step).toFixed(3)})`);
      // Stable lines: the fastest point is a 1→2 point, ½ edge per unit of factor, plus 2^-16
      // of rounding per step. `even`: the point 1/f moves at 1/f² ≤ 1. D3D11's fractional
      // modes move every half-edge point at once; their bound is looser.
      const bound = mode.startsWith('fractional') ? 2 : mode === 'even' ? 1.1 : 0.6;
      expect(C).toBeLessThan(bound);
    });
  }
  it(`hable: the top octave, 64 to MAX_FACTOR (${MAX_FACTOR}), moves every point continuously too`, () => {
    // Coarser steps than above (the octave is the same construction, twice as many points):
    // the bound scales with the step.
    const top = 4e-3;
    let prev = line('hable', 64).x;
    let worst = 0;
    for (let i = 1; 64 + i * top <= MAX_FACTOR; i++) {
      const cur = line('hable', 64 + i * top).x;
      worst = Math.max(worst, hausdorffSorted(prev, cur) / ONE);
      prev = cur;
    }
    expect(prev.length).toBe(MAX_FACTOR + 1);
    expect(worst / top).toBeLessThan(0.6);
  });
  it('pow2-snap pops (the point of the first figure)', () => {
    const gap = hausdorffSorted(line('pow2-snap', 3.999).x, line('pow2-snap', 4).x) / ONE;
    expect(gap).toBeGreaterThan(0.1);
  });
});

describe('hable: the stable line', () => {
  it('is exactly uniform at every power of two', () => {
    for (const maxFactor of [64, 128, 256]) {
      for (let N = 1; N <= maxFactor; N *= 2) {
        const { x, moving } = line('hable', N, { maxFactor });
        expect(x).toEqual(Array.from({ length: N + 1 }, (_, k) => (k * ONE) / N));
        expect(moving.every((m) => !m)).toBe(true);
      }
    }
  });

  it('keeps the points k/N of octave [N, 2N] in place throughout the octave', () => {
    fc.assert(
      fc.property(fc.double({ min: 2, max: 64, noNaN: true }), (f) => {
        const F = factorToFixed(f) / ONE;
        const N = 2 ** Math.floor(Math.log2(F));
        const { x } = line('hable', f);
        const set = new Set(x);
        for (let k = 0; k <= N; k++) expect(set.has((k * ONE) / N)).toBe(true);
      }),
      { numRuns: 2000 },
    );
  });

  it('slides each new point from its left neighbour to its place on the 2N grid', () => {
    const slots = buildSlots(64, HABLE_OPTIONS);
    for (const s of slots) {
      if (s.f0 < 0) continue;
      expect(slotPosition(s, s.f0)).toBe(s.x0);
      expect(slotPosition(s, s.f0 + s.w)).toBe(s.x1);
      // Monotone slide; present slots leave the parent immediately (ceil rounding).
      const mid = slotPosition(s, s.f0 + Math.floor(s.w / 2));
      expect((mid - s.x0) * (s.x1 - s.x0)).toBeGreaterThan(0);
      expect(Math.abs(slotPosition(s, s.f0 + 1) - s.x0)).toBeGreaterThanOrEqual(1);
      // The u32 bound the GPU relies on.
      expect(Math.abs(s.x1 - s.x0) * s.w + s.w).toBeLessThan(2 ** 32);
    }
  });

  it('inserts odd points before even ones in every octave (recursively)', () => {
    const slots = cachedSlots(64, HABLE_OPTIONS);
    for (let N = 4; N < 64; N *= 2) {
      const births = slots
        .filter((s) => s.f0 >= N * ONE && s.f0 < 2 * N * ONE)
        .sort((a, b) => a.f0 - b.f0)
        .map((s) => (s.x0 * N) / ONE); // j of each new point, in birth order
      expect(births.length).toBe(N);
      expect(births.slice(0, N / 2).every((j) => j % 2 === 1)).toBe(true);
      expect(births.slice(N / 2).every((j) => j % 2 === 0)).toBe(true);
      // within the odd ones, again odd (of j >> 1) first
      expect(births.slice(0, N / 4).every((j) => (j >> 1) % 2 === 1)).toBe(true);
    }
    // Half way through 4 → 8 one-at-a-time odd-first gives the balanced B s s B s s.
    const half = line('odd-first', 6).x;
    const seg = half.slice(1).map((v, i) => (v - half[i]) / ONE);
    expect(seg).toEqual([0.25, 0.125, 0.125, 0.25, 0.125, 0.125]);
  });

  it('slides several points together, slowly (one-at-a-time slides one)', () => {
    let maxHable = 0,
      maxOne = 0;
    for (let f = 1; f <= 64; f += 0.01) {
      maxHable = Math.max(maxHable, line('hable', f).moving.filter(Boolean).length);
      maxOne = Math.max(maxOne, line('one-at-a-time', f).moving.filter(Boolean).length);
    }
    expect(maxOne).toBe(1);
    expect(maxHable).toBeGreaterThanOrEqual(3);
  });

  it('goes from 1 to 2 with two points from both ends that meet in the middle', () => {
    expect(line('hable', 1).x).toEqual([0, ONE]);
    for (const f of [1.001, 1.25, 1.5, 1.75, 1.999]) {
      const { x } = line('hable', f);
      expect(x.length).toBe(4);
      expect(x[1] + x[2]).toBe(ONE); // symmetric
      expect(x[1]).toBeLessThanOrEqual(ONE / 2);
    }
    expect(line('hable', 1.5).x).toEqual([0, ONE / 4, (3 * ONE) / 4, ONE]);
    expect(line('hable', 2).x).toEqual([0, ONE / 2, ONE]);
  });

  it('is not mirror-symmetric (so edges need a direction) and reverses exactly', () => {
    const p = line('hable', 5.5);
    const r = reversed(p);
    expect(r.x).not.toEqual(p.x);
    expect(reversed(r)).toEqual(p);
  });

  it('takes the factor as float32 then 16.16 fixed point (what a shader sees)', () => {
    expect(stableFactorFixed(10.3, 64)).toBe(factorToFixed(Math.fround(10.3)));
    expect(line('hable', 10.3)).toEqual(line('hable', Math.fround(10.3)));
  });
});

describe("the talk's intermediate lines", () => {
  it('one-at-a-time at 3 is lopsided: two small segments, one big', () => {
    const { x } = line('one-at-a-time', 3);
    expect(x).toEqual([0, ONE / 4, ONE / 2, ONE]);
  });
  it('even at 10.3: ten segments of 1/10.3 and one of 0.3/10.3', () => {
    const { x } = line('even', 10.3);
    expect(x.length).toBe(12);
    const seg = x.slice(1).map((v, i) => (v - x[i]) / ONE);
    for (let i = 0; i < 10; i++) expect(seg[i]).toBeCloseTo(1 / 10.3, 4);
    expect(seg[10]).toBeCloseTo(0.3 / 10.3, 4);
  });
  it('even lands on the uniform grid at integers', () => {
    for (const n of [1, 2, 3, 7, 16, 64])
      expect(line('even', n).x).toEqual(Array.from({ length: n + 1 }, (_, k) => Math.floor((k * ONE) / n)));
  });
});

describe("Hable's line: how long its segments are (what the factor rule's chord error assumes)", () => {
  /** The longest segment of the line at factor F, as a fraction of the edge. */
  const longest = (F: number) => {
    const { x } = line('hable', F);
    let L = 0;
    for (let i = 1; i < x.length; i++) L = Math.max(L, (x[i] - x[i - 1]) / ONE);
    return L;
  };

  /** The largest (L·F)² over F in [a, b], on a 1/64 grid. */
  const worst = (a: number, b: number) => {
    let w = 0;
    for (let F = a; F <= b; F += 1 / 64) w = Math.max(w, (longest(F) * F) ** 2);
    return w;
  };

  it('is uniform (1/F) at powers of two, and up to 1.89/F between them', () => {
    for (const F of [1, 2, 4, 8, 16, 32, 64]) expect(longest(F) * F).toBeCloseTo(1, 9);
    // The factor rule (src/gpu/tess/factors.ts) asks for k equal segments, chord error |e|/k²; the
    // pattern's longest segment at F = k sags (L·F)² times more. Per octave (measured on a finer
    // grid: 1.50 at F 2.80, 2.04 at 5.71, 2.68 at 13.09, 3.20 at 28.63, 3.56 at 60.34), growing
    // towards 4: late in an octave of N a segment 1/N long is still unsplit.
    expect(worst(1, 2)).toBeLessThanOrEqual(1 + 1e-9); // two points from both ends: never longer
    const bounds: [number, number, number, number][] = [
      [2, 4, 1.45, 1.51],
      [4, 8, 1.98, 2.05],
      [8, 16, 2.6, 2.69],
      [16, 32, 3.1, 3.21],
      [32, 64, 3.5, 3.56],
    ];
    for (const [a, b, lo, hi] of bounds) {
      const w = worst(a, b);
      expect(w, `octave [${a}, ${b}]`).toBeGreaterThan(lo);
      expect(w, `octave [${a}, ${b}]`).toBeLessThanOrEqual(hi);
    }
  });
});
