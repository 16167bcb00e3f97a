/**
 * Unit tests for the D3D11 reference partitionings (src/pattern/d3d11.ts).
 *
 * Self-contained: the literal values come from Microsoft's D3D11 tessellator reference (its fractional partitionings) and
 * the golden data's README; the full golden comparison is `npm run check:golden` (CI).
 */
import { describe, it, expect } from 'vitest';
import fc from 'fast-check';
import { RULER_BIRTH_ORDER, d3d11Line, d3d11SegmentCount, d3d11TriCounts, d3d11Triangle } from '../../src/pattern/d3d11';
import { ONE } from '../../src/pattern/fixed';
import { D3D11_PARTITIONINGS, type D3D11Partitioning, type TriPattern } from '../../src/pattern/types';

type Tri3 = [number, number, number];
/** Where fractional_even rows are not monotone (see 'folds like the reference'). */
const inFoldWindow = (f: number) => {
  const F = Math.round(Math.fround(f) * ONE);
  return (F > 6 * ONE && F <= 6 * ONE + 6) || (F > 30 * ONE && F <= 30 * ONE + 414);
};
const FRACTIONAL: D3D11Partitioning[] = ['fractional_odd', 'fractional_even'];
const HW: D3D11Partitioning[] = ['integer', 'fractional_odd', 'fractional_even'];

const unit = (xs: number[]) => xs.map((x) => x / ONE);
const isMonotone = (x: number[]) => x.every((v, i) => i === 0 || v >= x[i - 1]);
/** Smallest step between neighbours of a row (Infinity for fewer than two points). */
const minGap = (x: number[]) => x.reduce((g, v, i) => (i === 0 ? g : Math.min(g, v - x[i - 1])), Infinity);
/** Measured over ~10^6 near-epoch triangles: flips need a row gap ≤ 14 units (fractional_odd;
 * 7 for fractional_even) and have a doubled area ≤ 70,091 units² (2^32 for the whole domain);
 * a fold (≤ 7 units wide, apex up to ½ away) stays below 7·ONE/2. */
const SLIVER_GAP = 16;
const SLIVER_AREA = 4 * ONE;

// ---------------------------------------------------------------------------------------------
// Mesh checks shared by the literal and the property tests
// ---------------------------------------------------------------------------------------------

/** Twice the signed area of triangle t in (u, v), exact (|value| < 2^34). */
function cross2(m: TriPattern, t: number): number {
  const [a, b, c] = [m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]];
  const ua = m.bary[3 * a],
    va = m.bary[3 * a + 1];
  const ub = m.bary[3 * b],
    vb = m.bary[3 * b + 1];
  const uc = m.bary[3 * c],
    vc = m.bary[3 * c + 1];
  return (ub - ua) * (vc - va) - (vb - va) * (uc - ua);
}

/** Throws (through expect) on the first violated mesh property. */
function checkMesh(p: D3D11Partitioning, factors: Tri3, inside: number, m: TriPattern): void {
  const counts = d3d11TriCounts(p, factors, inside);
  expect([m.vertexCount, m.triangleCount]).toEqual([counts.vertexCount, counts.triangleCount]);
  expect(m.bary.length).toBe(3 * m.vertexCount);
  expect(m.triangles.length).toBe(3 * m.triangleCount);
  if (m.vertexCount === 0) return;

  // Barycentrics: integers in [0, ONE] summing to ONE.
  for (let i = 0; i < m.vertexCount; i++) {
    const [u, v, w] = [m.bary[3 * i], m.bary[3 * i + 1], m.bary[3 * i + 2]];
    if (!(Number.isInteger(u) && Number.isInteger(v) && u >= 0 && v >= 0 && w >= 0 && u + v + w === ONE)) {
      expect.fail(`vertex ${i} = (${u}, ${v}, ${w})`);
    }
  }
  // Orientation and exact area: the domain (u, v ≥ 0, u + v ≤ 1) has doubled area ONE².
  // Integer/pow2 never flip a triangle. The reference's fractional modes do, as hairline
  // slivers, in two situations (see 'flips hairlines like the reference'): a fractional_even
  // fold, and a newborn pair still within a few units of its twin, whose ring projections
  // round to a locally non-convex corner.
  const rows = [...factors, inside].map((f) => d3d11Line(p, f).x);
  const nearBirth = rows.some((x) => !isMonotone(x) || minGap(x) <= SLIVER_GAP);
  let area = 0;
  for (let t = 0; t < m.triangleCount; t++) {
    const a2 = cross2(m, t);
    if (a2 < 0 && (!nearBirth || -a2 > SLIVER_AREA)) expect.fail(`triangle ${t} is flipped (${a2})`);
    area += a2;
  }
  expect(area).toBe(ONE * ONE);

  // Edges: each directed edge once; the outer ring's edges once, every other edge twice.
  const used = new Set<number>();
  const undirected = new Map<number, number>();
  const key = (a: number, b: number) => a * 65536 + b;
  for (let t = 0; t < m.triangleCount; t++) {
    for (let e = 0; e < 3; e++) {
      const a = m.triangles[3 * t + e];
      const b = m.triangles[3 * t + ((e + 1) % 3)];
      if (a < 0 || a >= m.vertexCount) expect.fail(`index ${a} out of range`);
      if (used.has(key(a, b))) expect.fail(`directed edge ${a}->${b} used twice`);
      used.add(key(a, b));
      const k = key(Math.min(a, b), Math.max(a, b));
      undirected.set(k, (undirected.get(k) ?? 0) + 1);
    }
  }
  const outer = factors.reduce((s, f) => s + d3d11SegmentCount(p, f), 0);
  const boundary = new Set<number>();
  if (m.vertexCount === 3 && m.triangleCount === 1) {
    boundary.add(key(0, 1)).add(key(1, 2)).add(key(0, 2));
  } else {
    for (let i = 0; i < outer; i++) {
      const j = (i + 1) % outer;
      boundary.add(key(Math.min(i, j), Math.max(i, j)));
    }
  }
  for (const [k, n] of undirected) {
    const want = boundary.has(k) ? 1 : 2;
    if (n !== want) expect.fail(`edge ${Math.floor(k / 65536)}-${k % 65536} used ${n} times`);
  }
  expect([...boundary].every((k) => undirected.get(k) === 1)).toBe(true);
}

/** The outer ring read back as three edges, each in its isoline's own direction (0 → ONE). */
function outerEdges(p: D3D11Partitioning, factors: Tri3, m: TriPattern): number[][] {
  const s = factors.map((f) => d3d11SegmentCount(p, f));
  const total = s[0] + s[1] + s[2];
  const pt = (i: number) => [m.bary[3 * (i % total)], m.bary[3 * (i % total) + 1]];
  const e0: number[] = []; // U==0, V decreasing: v read backwards
  const e1: number[] = []; // V==0, U increasing
  const e2: number[] = []; // W==0, U decreasing (v = 1 − u): u read backwards
  for (let i = 0; i <= s[0]; i++) {
    const [u, v] = pt(i);
    expect(u).toBe(0);
    e0.unshift(v);
  }
  for (let i = s[0]; i <= s[0] + s[1]; i++) {
    const [u, v] = pt(i);
    expect(v).toBe(0);
    e1.push(u);
  }
  for (let i = s[0] + s[1]; i <= total; i++) {
    const [u, v] = pt(i);
    expect(u + v).toBe(ONE);
    e2.unshift(u);
  }
  return [e0, e1, e2];
}

// ---------------------------------------------------------------------------------------------
// Tables and segment counts
// ---------------------------------------------------------------------------------------------

describe('d3d11 tables', () => {
  it('derives the 33-entry ruler table of the reference tessellator', () => {
    expect(RULER_BIRTH_ORDER).toEqual([
      0, 32, 16, 8, 17, 4, 18, 9, 19, 2, 20, 10, 21, 5, 22, 11, 23, 1, 24, 12, 25, 6, 26, 13, 27, 3, 28, 14, 29, 7, 30, 15, 31,
    ]);
  });

  it('counts segments as the reference tessellator does', () => {
    const cases: [D3D11Partitioning, number, number][] = [
      ['integer', 1, 1],
      ['integer', 1.01, 2],
      ['integer', 2.01, 3],
      ['pow2', 1, 1],
      ['pow2', 1.01, 2],
      ['pow2', 2.01, 4],
      ['pow2', 5, 8],
      ['pow2', 33, 64],
      ['fractional_odd', 1, 1],
      ['fractional_odd', 1.01, 3],
      ['fractional_odd', 3, 3],
      ['fractional_odd', 3.01, 5],
      ['fractional_odd', 64, 63],
      ['fractional_even', 1, 2],
      ['fractional_even', 2, 2],
      ['fractional_even', 2.01, 4],
      ['fractional_even', 4.01, 6],
    ];
    for (const [p, f, s] of cases) expect(d3d11SegmentCount(p, f), `${p} ${f}`).toBe(s);
    for (const p of D3D11_PARTITIONINGS) {
      for (const f of [0, -0, -1, NaN, -Infinity]) expect(d3d11SegmentCount(p, f)).toBe(0);
      expect(d3d11SegmentCount(p, Infinity)).toBe(p === 'fractional_odd' ? 63 : 64);
    }
  });
});

// ---------------------------------------------------------------------------------------------
// Isoline
// ---------------------------------------------------------------------------------------------

describe('d3d11Line', () => {
  it('reproduces the reference tessellator outputs (4 decimals)', () => {
    const cases: [D3D11Partitioning, number, number[]][] = [
      ['fractional_even', 4, [0, 0.25, 0.5, 0.75, 1]],
      ['fractional_even', 4.5, [0, 0.2292, 0.2708, 0.5, 0.7292, 0.7708, 1]],
      ['fractional_even', 5, [0, 0.2083, 0.2917, 0.5, 0.7083, 0.7917, 1]],
      ['fractional_even', 6, [0, 0.1667, 0.3333, 0.5, 0.6667, 0.8333, 1]],
      ['fractional_even', 6.5, [0, 0.1562, 0.3125, 0.4688, 0.5, 0.5312, 0.6875, 0.8438, 1]],
      ['fractional_even', 7, [0, 0.1458, 0.2917, 0.4375, 0.5, 0.5625, 0.7083, 0.8542, 1]],
      ['fractional_even', 8, [0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1]],
      ['fractional_even', 2.25, [0, 0.4688, 0.5, 0.5312, 1]],
      ['fractional_odd', 1.25, [0, 0.0417, 0.9583, 1]],
      ['fractional_odd', 1.5, [0, 0.0833, 0.9167, 1]],
      ['fractional_odd', 2, [0, 0.1667, 0.8333, 1]],
      ['fractional_odd', 3, [0, 0.3333, 0.6667, 1]],
      ['fractional_odd', 3.5, [0, 0.3, 0.35, 0.65, 0.7, 1]],
    ];
    for (const [p, f, want] of cases) {
      const got = unit(d3d11Line(p, f).x);
      expect(got.length, `${p} ${f}`).toBe(want.length);
      got.forEach((x, i) => expect(Math.abs(x - want[i]), `${p} ${f} [${i}]`).toBeLessThan(6e-5));
    }
  });

  it('matches golden cases that catch the float32-first and ties-to-even traps', () => {
    // Golden README: converting the double directly changes fractional_odd 55.059; rounding
    // float32 ties upward changes fractional_even 41.443.
    expect(d3d11Line('fractional_odd', 55.059).x).toEqual([
      0, 1191, 2382, 3572, 4763, 5954, 7145, 8335, 9526, 10717, 11908, 13098, 14289, 15480, 16671, 17861, 19052, 20243, 21434, 22624, 23815,
      25006, 26197, 27388, 27421, 28612, 29803, 30994, 32184, 33352, 34542, 35733, 36924, 38115, 38148, 39339, 40530, 41721, 42912, 44102,
      45293, 46484, 47675, 48865, 50056, 51247, 52438, 53628, 54819, 56010, 57201, 58391, 59582, 60773, 61964, 63154, 64345, 65536,
    ]);
    expect(d3d11Line('fractional_even', 41.443).x).toEqual([
      0, 1582, 3163, 4745, 6327, 7909, 9490, 11072, 12654, 14236, 15361, 16943, 18524, 20106, 21688, 23270, 24851, 26433, 28015, 29597,
      31178, 32768, 34358, 35939, 37521, 39103, 40685, 42266, 43848, 45430, 47012, 48593, 50175, 51300, 52882, 54464, 56046, 57627, 59209,
      60791, 62373, 63954, 65536,
    ]);
  });

  it('culls, clamps and rounds like the golden edge family', () => {
    for (const p of D3D11_PARTITIONINGS) {
      for (const f of [0, -1, NaN]) expect(d3d11Line(p, f)).toEqual({ x: [], moving: [] });
      const lower = d3d11Line(p, p === 'fractional_even' ? 2 : 1);
      for (const f of [1e-6, 0.5, 0.999]) expect(d3d11Line(p, f)).toEqual(lower);
      const upper = d3d11Line(p, p === 'fractional_odd' ? 63 : 64);
      for (const f of [63.5, 64.5, 70, Infinity]) {
        if (p === 'fractional_odd' || f > 64) expect(d3d11Line(p, f)).toEqual(upper);
      }
    }
    expect(d3d11Line('integer', 1.125).x).toEqual([0, ONE / 2, ONE]);
    expect(d3d11Line('integer', 3).x).toEqual([0, 21845, 43691, ONE]);
    expect(d3d11Line('pow2', 5)).toEqual(d3d11Line('integer', 8));
    expect(d3d11Line('pow2', 4)).toEqual(d3d11Line('integer', 4));
    expect(d3d11Line('pow2', 33)).toEqual(d3d11Line('integer', 64));
    expect(d3d11Line('pow2', 0.3)).toEqual(d3d11Line('integer', 1));
  });

  it('marks the split pair and its mirror as moving', () => {
    const m = (p: D3D11Partitioning, f: number) => d3d11Line(p, f).moving;
    expect(m('fractional_even', 2.25)).toEqual([false, true, false, true, false]);
    expect(m('fractional_even', 4.5)).toEqual([false, true, true, false, true, true, false]);
    expect(m('fractional_odd', 1.25)).toEqual([false, true, true, false]);
    expect(m('fractional_odd', 3.5)).toEqual([false, true, true, true, true, false]);
    // 6.5: half factor 3.25, split point σ = 3, so the pair is (.4688, .5) and its mirror.
    expect(m('fractional_even', 6.5)).toEqual([false, false, false, true, false, true, false, false, false]);
    for (const f of [2, 4, 8, 64]) expect(m('fractional_even', f).some(Boolean)).toBe(false);
    for (const f of [1, 3, 5, 63]) expect(m('fractional_odd', f).some(Boolean)).toBe(false);
    for (const f of [1.5, 7.25, 33.3]) {
      expect(m('integer', f).some(Boolean)).toBe(false);
      expect(m('pow2', f).some(Boolean)).toBe(false);
    }
  });

  it('is sorted, 0 first, ONE last, symmetric, and has d3d11SegmentCount + 1 points', () => {
    fc.assert(
      fc.property(
        fc.constantFrom(...D3D11_PARTITIONINGS),
        fc.oneof(fc.double({ min: 0.5, max: 70, noNaN: true }), fc.integer({ min: 1, max: 64 })),
        (p, f) => {
          const { x, moving } = d3d11Line(p, f);
          expect(x.length).toBe(d3d11SegmentCount(p, f) + 1);
          expect(moving.length).toBe(x.length);
          expect(x[0]).toBe(0);
          expect(x[x.length - 1]).toBe(ONE);
          // Non-decreasing (new points are born on top of old ones, so equal neighbours occur
          // just above an epoch), except in the fractional_even fold windows.
          if (!isMonotone(x)) expect(p === 'fractional_even' && inFoldWindow(f)).toBe(true);
          for (let i = 0; i < x.length; i++) {
            if (!Number.isInteger(x[i]) || x[i] + x[x.length - 1 - i] !== ONE) expect.fail(`asymmetric at ${i}`);
            if (moving[i] !== moving[x.length - 1 - i]) expect.fail(`moving asymmetric at ${i}`);
          }
        },
      ),
      { numRuns: 3000 },
    );
  });

  it('folds like the reference just above fractional_even 6 and 30', () => {
    // The 1/30 entry of the reference's reciprocal table is rounded up (0x889), so
    // 15 · 0x889 = 0x8007 lands past the midpoint: just above f = 30 (and, by one unit, just
    // above f = 6, 3 · 0x2aab = 0x8001) the point before the midpoint sits beyond it until the
    // blend pulls it back. The reference emits these points in that order; so do we.
    const x = d3d11Line('fractional_even', 30.001).x;
    expect(x.slice(14, 19)).toEqual([30589, 32774, 32768, 32762, 34947]);
    // Every 16.16 factor within 1000 units above each even epoch: the folds are exactly these.
    const folds: number[] = [];
    for (let e = 2; e < 64; e += 2) {
      for (let k = 1; k <= 1000; k++) {
        if (!isMonotone(d3d11Line('fractional_even', e + k / ONE).x)) folds.push(e * ONE + k);
      }
    }
    const expected = [...Array.from({ length: 6 }, (_, i) => 6 * ONE + 1 + i), ...Array.from({ length: 414 }, (_, i) => 30 * ONE + 1 + i)];
    expect(folds).toEqual(expected);
    expect(expected.every((F) => inFoldWindow(F / ONE))).toBe(true);
    // In a triangle, the folded edge gives two hairline triangles of opposite orientation.
    const m = d3d11Triangle('fractional_even', [30.001, 4, 4], 4);
    const areas = Array.from({ length: m.triangleCount }, (_, t) => cross2(m, t));
    expect(areas.filter((a) => a < 0).length).toBe(2);
    checkMesh('fractional_even', [30.001, 4, 4], 4, m);
    // A folded inside factor folds every ring side: (2, 2, 2) / 6 + 2^-15 has 30 of its 78
    // triangles flipped, each with a doubled area of 7282 units² (out of 2^32).
    const r = d3d11Triangle('fractional_even', [2, 2, 2], 6 + 2 ** -15);
    const ringAreas = Array.from({ length: r.triangleCount }, (_, t) => cross2(r, t));
    expect([r.triangleCount, ringAreas.filter((a) => a < 0).length]).toEqual([78, 30]);
    expect(ringAreas.every((a) => a >= 0 || a === -7282)).toBe(true);
    checkMesh('fractional_even', [2, 2, 2], 6 + 2 ** -15, r);
    // fractional_odd never folds (its middle is a segment, and (H−1)/(2H−1) stays clear of ½).
    for (let e = 1; e < 63; e += 2) {
      for (let k = 1; k <= 200; k += 7) expect(isMonotone(d3d11Line('fractional_odd', e + k / ONE).x)).toBe(true);
    }
  });

  it('is continuous in the factor for the fractional modes', () => {
    // Hausdorff distance between the point sets at f and f + 1e-3 (both sorted), in units of
    // the parameter, over the whole clamped range.
    const hausdorff = (a: number[], b: number[]) => {
      const oneWay = (p: number[], q: number[]) => {
        let worst = 0;
        let j = 0;
        for (const x of p) {
          while (j + 1 < q.length && q[j + 1] <= x) j++;
          const d = Math.min(Math.abs(x - q[j]), j + 1 < q.length ? Math.abs(q[j + 1] - x) : Infinity);
          worst = Math.max(worst, d);
        }
        return worst;
      };
      const [sa, sb] = [[...a].sort((u, v) => u - v), [...b].sort((u, v) => u - v)];
      return Math.max(oneWay(sa, sb), oneWay(sb, sa)) / ONE;
    };
    const step = 1e-3;
    const measured: Record<string, { max: number; at: number }> = {};
    for (const p of FRACTIONAL) {
      const [lo, hi] = p === 'fractional_odd' ? [1, 63] : [2, 64];
      let prev = d3d11Line(p, lo).x;
      let max = 0;
      let at = lo;
      const n = Math.round((hi - lo) / step);
      for (let i = 1; i <= n; i++) {
        const f = lo + i * step;
        const cur = d3d11Line(p, f).x;
        const d = hausdorff(prev, cur);
        if (d > max) {
          max = d;
          at = f;
        }
        prev = cur;
      }
      measured[p] = { max, at };
    }
    console.log(
      `d3d11 continuity (Hausdorff per 1e-3 factor step): ` +
        FRACTIONAL.map(
          (p) => `${p} ${measured[p].max.toFixed(6)} (at f≈${measured[p].at.toFixed(3)}, ` + `L≈${(measured[p].max / step).toFixed(3)})`,
        ).join(', '),
    );
    // A step of 1e-3 moves no point by more than ~1/6 of it (odd 1→3: x = (f−1)/6), plus the
    // 2^-16 grid of the factor and of the result.
    for (const p of FRACTIONAL) expect(measured[p].max).toBeLessThan(2.5e-4);
  });
});

// ---------------------------------------------------------------------------------------------
// Triangle domain
// ---------------------------------------------------------------------------------------------

// V / T for integer (= pow2 in hardware), fractional_odd, fractional_even: the closed forms of
// src/pattern/d3d11.ts and the golden README's spec, extra and edge tables.
const COUNT_TABLE: [Tri3, number, [number, number] | null, [number, number] | null, [number, number]][] = [
  [[1, 1, 1], 1, [3, 1], [3, 1], [7, 6]],
  [[2, 2, 2], 2, [7, 6], [12, 13], [7, 6]],
  [[3, 3, 3], 3, [12, 13], [12, 13], [19, 24]],
  [[4, 4, 4], 4, [19, 24], [27, 37], [19, 24]],
  [[8, 8, 8], 8, [61, 96], [75, 121], [61, 96]],
  [[10.3, 10.3, 10.3], 10.3, [108, 181], [108, 181], [127, 216]],
  [[16, 16, 16], 16, [217, 384], [243, 433], [217, 384]],
  [[32, 32, 32], 32, [817, 1536], [867, 1633], [817, 1536]],
  [[64, 64, 64], 64, [3169, 6144], [3072, 5953], [3169, 6144]],
  [[2, 3, 4], 5, [21, 31], [23, 33], [29, 46]],
  [[4, 4, 4], 1, [13, 12], [18, 19], [13, 12]],
  [[1, 1, 16], 16, [187, 354], [211, 401], [189, 356]],
  [[2, 2, 2], 16, [175, 342], [201, 391], [175, 342]],
  [[16, 16, 16], 2, [49, 48], [54, 55], [49, 48]],
  [[1.5, 1, 1], 1, [5, 4], [8, 9], [7, 6]],
  [[1.01, 1, 1], 1.01, [5, 4], [8, 9], [7, 6]],
  [[1, 1, 1], 1.01, [4, 3], [6, 7], [7, 6]],
  [[1.01, 1.01, 1.01], 1.01, [7, 6], [12, 13], [7, 6]],
  [[2.001, 2, 2], 2, [8, 7], [12, 13], [9, 8]],
  [[2.001, 2.001, 2.001], 2.001, [12, 13], [12, 13], [19, 24]],
  [[1, 2, 3], 1, [7, 6], [10, 11], [9, 8]],
  [[5, 1, 9], 2.5, [18, 19], [18, 19], [25, 30]],
  [[4.5, 6.25, 7.75], 3.5, [27, 32], [33, 43], [29, 34]],
  // edge family
  [[0, 4, 4], 4, [0, 0], [0, 0], [0, 0]],
  [[4, 0, 4], 4, [0, 0], [0, 0], [0, 0]],
  [[4, 4, 0], 4, [0, 0], [0, 0], [0, 0]],
  [[4, -1, 4], 4, [0, 0], [0, 0], [0, 0]],
  [[-2, -2, -2], -2, [0, 0], [0, 0], [0, 0]],
  [[NaN, 4, 4], 4, [0, 0], [0, 0], [0, 0]],
  [[4, 4, NaN], 4, [0, 0], [0, 0], [0, 0]],
  [[4, 4, 4], NaN, [13, 12], [18, 19], [13, 12]],
  [[1, 1, 1], NaN, [3, 1], [3, 1], [7, 6]],
  [[2.5, 3.5, 7], NaN, [15, 14], [18, 19], [17, 16]],
  [[4, 4, 4], 0, [13, 12], [18, 19], [13, 12]],
  [[4, 4, 4], -5, [13, 12], [18, 19], [13, 12]],
  [[1, 1, 1], 0, [3, 1], [3, 1], [7, 6]],
  [[0.5, 0.5, 0.5], 0.5, [3, 1], [3, 1], [7, 6]],
  [[1e-6, 1, 1], 1, [3, 1], [3, 1], [7, 6]],
  [[70, 70, 70], 70, [3169, 6144], [3072, 5953], [3169, 6144]],
  [[70, 3, 5], 70, [3049, 6024], [2954, 5835], [3051, 6026]],
  [[64.5, 63.5, 63.01], 63.5, [3169, 6144], [3072, 5953], [3169, 6144]],
  [[Infinity, 4, 4], 4, [79, 84], [85, 95], [79, 84]],
  [[4, 4, 4], Infinity, [2989, 5964], [2898, 5779], [2989, 5964]],
  [[4, 4, 4], -Infinity, [13, 12], [18, 19], [13, 12]],
];

describe('d3d11Triangle', () => {
  it('has the reference vertex / triangle counts (D3D11 reference tessellator, golden README)', () => {
    for (const [factors, inside, integer, odd, even] of COUNT_TABLE) {
      const want: [D3D11Partitioning, [number, number] | null][] = [
        ['integer', integer],
        ['fractional_odd', odd],
        ['fractional_even', even],
      ];
      for (const [p, vt] of want) {
        if (!vt) continue;
        const label = `${p} (${factors.join(', ')}) / ${inside}`;
        const m = d3d11Triangle(p, factors, inside);
        expect([m.vertexCount, m.triangleCount], label).toEqual(vt);
        const c = d3d11TriCounts(p, factors, inside);
        expect([c.vertexCount, c.triangleCount], label).toEqual(vt);
        checkMesh(p, factors, inside, m);
      }
    }
  });

  it('uses the reference point order and the CW single triangle', () => {
    expect(d3d11Triangle('integer', [1, 1, 1], 1)).toEqual({
      bary: [0, ONE, 0, 0, 0, ONE, ONE, 0, 0],
      triangles: [0, 1, 2],
      vertexCount: 3,
      triangleCount: 1,
    });
    const m = d3d11Triangle('integer', [2, 2, 2], 2);
    const h = ONE / 2;
    expect(m.bary).toEqual([0, ONE, 0, 0, h, h, 0, 0, ONE, h, 0, h, ONE, 0, 0, h, h, 0, 0x5555, 0x5555, 0x5556]);
    expect(m.triangles).toEqual([0, 1, 6, 1, 2, 6, 2, 3, 6, 3, 4, 6, 4, 5, 6, 5, 0, 6]);
    // The even centre is the last point and is not symmetric: w gets the extra unit.
    const e = d3d11Triangle('fractional_even', [5, 6, 7], 9);
    expect(e.bary.slice(-3)).toEqual([0x5555, 0x5555, 0x5556]);
  });

  it('collapses the forced fractional_odd picture frame onto the corners', () => {
    for (const [factors, inside] of [
      [[4, 4, 4], 1],
      [[1.5, 1, 1], 1],
      [[1, 2, 3], 1],
      [[4, 4, 4], NaN],
      [[2.5, 3.5, 7], NaN],
      [[4, 4, 4], 0],
      [[4, 4, 4], -5],
      [[4, 4, 4], -Infinity],
    ] as [Tri3, number][]) {
      const m = d3d11Triangle('fractional_odd', factors, inside);
      const ring = m.bary.slice(-9);
      expect(ring).toEqual([0, ONE, 0, 0, 0, ONE, ONE, 0, 0]);
      const nonDegenerate = Array.from({ length: m.triangleCount }, (_, t) => cross2(m, t)).filter((a) => a !== 0);
      expect(nonDegenerate).toEqual([ONE * ONE]); // only the centre triangle, covering everything
      checkMesh('fractional_odd', factors, inside, m);
    }
  });

  it('flips hairlines like the reference just above a fractional epoch', () => {
    // Inside 8 + 13·2^-16: the newborn pair sits at 57343 / 57344, one unit apart; projected
    // onto the first ring (⅔ and a halved shift, both rounded) it makes a corner that is
    // non-convex by a unit, and two transition triangles come out slightly inverted.
    const inside = 8 + 13 / ONE;
    expect(d3d11Line('fractional_even', inside).x).toEqual([0, 8192, 8193, 16384, 24576, 32768, 40960, 49152, 57343, 57344, ONE]);
    const m = d3d11Triangle('fractional_even', [3, 3, 3], inside);
    const flipped = Array.from({ length: m.triangleCount }, (_, t) => [t, cross2(m, t)]).filter(([, a]) => a < 0);
    expect(flipped).toEqual([
      [22, -8191],
      [34, -13653],
    ]);
    checkMesh('fractional_even', [3, 3, 3], inside, m);
    // A little further from the epoch, nothing is flipped.
    const later = d3d11Triangle('fractional_even', [3, 3, 3], 8.01);
    expect(Array.from({ length: later.triangleCount }, (_, t) => cross2(later, t)).every((a) => a >= 0)).toBe(true);
  });

  it('treats pow2 as integer after rounding every factor up to a power of two', () => {
    expect(d3d11Triangle('pow2', [3, 5, 9], 8)).toEqual(d3d11Triangle('integer', [4, 8, 16], 8));
    expect(d3d11Triangle('pow2', [2, 3, 4], 3)).toEqual(d3d11Triangle('integer', [2, 4, 4], 4));
    expect(d3d11Triangle('pow2', [1, 1, 1], 1)).toEqual(d3d11Triangle('integer', [1, 1, 1], 1));
    expect(d3d11Triangle('pow2', [1, 1, 1], NaN)).toEqual(d3d11Triangle('integer', [1, 1, 1], 1));
    expect(d3d11Triangle('pow2', [0, 1, 1], 1).vertexCount).toBe(0);
    expect(d3d11TriCounts('pow2', [2, 3, 4], 3)).toEqual({ vertexCount: 17, triangleCount: 22 });
  });

  it('holds the mesh properties and the closed form for random factors', () => {
    // Mostly low factors (cheap and where the special cases live), sometimes the full range.
    const factor = fc.oneof(
      { weight: 6, arbitrary: fc.double({ min: 0.5, max: 12, noNaN: true }) },
      { weight: 2, arbitrary: fc.integer({ min: 1, max: 8 }) },
      { weight: 1, arbitrary: fc.double({ min: 0.9, max: 70, noNaN: true }) },
      { weight: 1, arbitrary: fc.constantFrom(1, 2, 3, 1 + 2 ** -17, 1 + 2 ** -16, 4 + 2 ** -16, 6 + 2 ** -15, 30.001, 63, 64, Infinity) },
    );
    const insideFactor = fc.oneof({ weight: 9, arbitrary: factor }, { weight: 1, arbitrary: fc.constantFrom(NaN, 0, -3, -Infinity) });
    fc.assert(
      fc.property(fc.constantFrom(...D3D11_PARTITIONINGS), fc.tuple(factor, factor, factor), insideFactor, (p, factors, inside) => {
        const m = d3d11Triangle(p, factors, inside);
        checkMesh(p, factors, inside, m);
        const edges = outerEdges(p, factors, m);
        for (let e = 0; e < 3; e++) expect(edges[e]).toEqual(d3d11Line(p, factors[e]).x);
      }),
      { numRuns: 3000 },
    );
  });

  it('culls on any edge ≤ 0 or NaN, whatever the inside factor', () => {
    fc.assert(
      fc.property(
        fc.constantFrom(...HW),
        fc.integer({ min: 0, max: 2 }),
        fc.constantFrom(0, -0, -1, -Infinity, NaN, 1e-50),
        fc.double({ min: 1, max: 64, noNaN: true }),
        (p, which, bad, f) => {
          const factors: Tri3 = [f, f, f];
          factors[which] = bad;
          expect(d3d11Triangle(p, factors, f)).toEqual({ bary: [], triangles: [], vertexCount: 0, triangleCount: 0 });
          expect(d3d11TriCounts(p, factors, f)).toEqual({ vertexCount: 0, triangleCount: 0 });
        },
      ),
      { numRuns: 300 },
    );
  });
});
