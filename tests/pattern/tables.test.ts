import { describe, it, expect } from 'vitest';
import fc from 'fast-check';
import { ONE } from '../../src/pattern/fixed.ts';
import { bakeTables, PatternTables, TABLE_MAGIC } from '../../src/pattern/tables.ts';
import { hableLine, buildSlots, HABLE_OPTIONS } from '../../src/pattern/hable-line.ts';
import { clampedTriangle } from '../../src/pattern/clamped.ts';

const tables = new Map<number, PatternTables>();
const get = (m: number) => {
  let t = tables.get(m);
  if (!t) tables.set(m, (t = new PatternTables(bakeTables(m))));
  return t;
};

describe('baked pattern tables', () => {
  it('have the documented header and reject bad bytes', () => {
    const w = bakeTables(64);
    expect(w[0]).toBe(TABLE_MAGIC);
    expect(w[1]).toBe(2);
    expect(w[2]).toBe(64);
    // No gap-matching records since version 2 (the plan pass computes them per triangle).
    expect([w[9], w[10]]).toEqual([w.length, 0]);
    expect(w[11]).toBe(w.length);
    expect(() => new PatternTables(new Uint32Array(4))).toThrow(/magic/);
    const bad = w.slice();
    bad[1] = 99;
    expect(() => new PatternTables(bad)).toThrow(/version/);
    expect(() => new PatternTables(w.slice(0, w.length - 1))).toThrow(/truncated/);
  });

  it('are small: at or below 1.6 MB at max factor 64', () => {
    expect(bakeTables(64).byteLength).toBeLessThanOrEqual(1.6e6);
  });

  it('store every slot of the schedule', () => {
    for (const m of [64, 128]) {
      const t = get(m);
      const slots = buildSlots(m, HABLE_OPTIONS);
      expect(t.slotCount).toBe(slots.length);
      slots.forEach((s, i) => {
        const d = t.slot(i);
        expect([d.x0, d.x1, d.w, d.death]).toEqual([s.x0, s.x1, s.w, s.death]);
      });
    }
  });

  it('reproduce the line exactly at every state boundary and at random factors', () => {
    for (const m of [64, 128]) {
      const t = get(m);
      const words = t.words;
      for (let k = 0; k < t.stateCount; k++) {
        const F = words[words[6] + k];
        for (const G of [F - 1, F, F + 1]) {
          if (G < ONE || G > m * ONE) continue;
          expect(t.line(G / ONE)).toEqual(hableLine(G / ONE, m));
        }
      }
      fc.assert(
        fc.property(fc.double({ min: 0.5, max: m + 1, noNaN: true }), (f) => {
          expect(t.line(f)).toEqual(hableLine(f, m));
        }),
        { numRuns: 3000 },
      );
    }
  });

  it('reproduce the clamped triangle exactly (points and indices)', () => {
    const f = fc.oneof(
      fc.double({ min: 1, max: 64, noNaN: true }),
      fc.integer({ min: 1, max: 64 }),
      fc.double({ min: 1, max: 2.5, noNaN: true }),
    );
    fc.assert(
      fc.property(fc.tuple(f, f, f), fc.tuple(fc.boolean(), fc.boolean(), fc.boolean()), (factors, reverse) => {
        expect(get(64).clampedTriangle(factors, reverse)).toEqual(clampedTriangle(factors, reverse));
      }),
      { numRuns: 2000 },
    );
    // and with a larger table
    fc.assert(
      fc.property(
        fc.tuple(
          fc.double({ min: 1, max: 128, noNaN: true }),
          fc.double({ min: 1, max: 128, noNaN: true }),
          fc.double({ min: 1, max: 128, noNaN: true }),
        ),
        (factors) => {
          expect(get(128).clampedTriangle(factors, [true, false, true])).toEqual(
            clampedTriangle(factors, [true, false, true], { maxFactor: 128 }),
          );
        },
      ),
      { numRuns: 200 },
    );
  });
});
