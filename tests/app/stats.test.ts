/** The stats panel's text (src/app/stats.ts): every figure current or marked as an older one's. */
import { describe, expect, it } from 'vitest';
import { ratio, renderStats, type StatsInput } from '../../src/app/stats.ts';
import { loadCage } from '../../src/mesh/index.ts';

const base: StatsInput = {
  model: null,
  counts: { vertexCount: 100, triangleCount: 200, budgetScale: 1, budgetCandidate: 0 },
  vertexCapacity: 1000,
  triangleCapacity: 1000,
  source: 'tessellator',
  mode: 'adaptive',
  tessTimes: { factors: 1, emit: 2 },
  drawTimes: { shadow: 1, lit: 2 },
  timestamps: true,
  frameMs: 16.7,
  jsMs: 0.5,
  rebuilds: 3,
  adapter: 'test',
  surface: { shown: 'phong' },
};

describe('stats', () => {
  it('says when the counts and the build timings are an older build’s, and not otherwise', () => {
    const now = renderStats(base);
    expect(now).not.toContain('building…');
    expect(now).not.toContain('the previous build');
    const older = renderStats({ ...base, countsStale: true, tessTimesStale: true });
    expect(older).toContain('building…');
    expect(older).toContain('the previous build; timing the new one');
  });

  it('marks the draw times as the last frame’s when nothing is drawn, and the frame as idle', () => {
    const idle = renderStats({ ...base, frameMs: 0 });
    expect(idle).toMatch(/lit 2\.00 <span class="muted">last frame<\/span>/);
    expect(idle).toContain('idle');
    expect(renderStats(base)).not.toContain('last frame');
  });

  it("says what the loader changed: a non-manifold cage's splits, the first in the row and all on hover", () => {
    const text = ['v 0 0 0', 'v 1 0 0', 'v 1 1 0', 'v -1 0 0', 'v -1 -1 0', 'f 1 2 3', 'f 1 4 5'].join('\n');
    const model = { ...loadCage(text), title: 'bowtie.obj' } as unknown as StatsInput['model'];
    const html = renderStats({ ...base, model });
    expect(html).toContain('non-manifold vertex 1: its faces form 2 fans');
    const clean = { ...loadCage('v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3'), title: 'x' } as unknown as StatsInput['model'];
    expect(renderStats({ ...base, model: clean })).not.toContain('class="warn"');
  });

  it('writes ratios with two significant digits, never 0.01× for a few hundredths', () => {
    expect(ratio(0.0085)).toBe('0.0085×');
    expect(ratio(0.42)).toBe('0.42×');
    expect(ratio(3.06)).toBe('3.1×');
    expect(ratio(12.4)).toBe('12×');
    const other = renderStats({
      ...base,
      other: { mode: 'fixed', setting: 'factor 8', counts: { vertexCount: 1, triangleCount: 3, budgetScale: 1, budgetCandidate: 0 } },
    });
    expect(other).toContain('0.015× the drawn tris');
  });

  it('puts "of the diagonal" after the distances, not after the angles', () => {
    const html = renderStats({
      ...base,
      errors: [
        {
          surface: 'gregory-acc',
          totals: { maxDistance: 0.001, rmsDistance: 0.0005, maxAngle: 2, rmsAngle: 1, vertices: 10 },
        } as NonNullable<StatsInput['errors']>[number],
      ],
    });
    expect(html.indexOf('of the diagonal')).toBeLessThan(html.indexOf('normal max'));
  });
});
