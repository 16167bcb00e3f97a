/** The demo's instanced counts (src/app/instanced-view.ts countsFromRecords) and their stats rows. */
import { describe, it, expect } from 'vitest';
import { countsFromRecords } from '../../src/app/instanced-view.ts';
import { renderStats, type StatsInput } from '../../src/app/stats.ts';
import { BUCKETS } from '../../src/gpu/instanced/buffer-layouts.ts';
import { packPatterns, patternTriangleCount, patternVertexCount } from '../../src/pattern/pow2.ts';

describe('instanced counts', () => {
  const patterns = packPatterns();
  // 3 quads at level 4, 2 quads at level 16, 5 triangles at level 1, as the records pass writes them.
  const records = new Uint32Array(5 * BUCKETS);
  const instances: Record<number, number> = { 2: 3, 4: 2, 7: 5 };
  patterns.entries.forEach((e, b) => records.set([e.indexCount, instances[b] ?? 0, e.firstIndex, e.baseVertex, 0], 5 * b));

  it('sums triangles, evaluated vertices and patches per level from the records', () => {
    const c = countsFromRecords(records, patterns);
    expect(c.patches).toBe(10);
    expect(c.triangles).toBe(
      3 * patternTriangleCount('quad', 4) + 2 * patternTriangleCount('quad', 16) + 5 * patternTriangleCount('tri', 1),
    );
    expect(c.vertices).toBe(3 * patternVertexCount('quad', 4) + 2 * patternVertexCount('quad', 16) + 5 * patternVertexCount('tri', 1));
    expect(c.levels).toEqual([
      [1, 5],
      [4, 3],
      [16, 2],
    ]);
  });

  it('the stats show them per pass, the buckets, and no compute-tessellator rows', () => {
    const input: StatsInput = {
      model: null,
      counts: { vertexCount: 1, triangleCount: 2, budgetScale: 1, budgetCandidate: 0 },
      vertexCapacity: 10,
      triangleCapacity: 10,
      source: 'tessellator',
      mode: 'fixed',
      tessTimes: { tessellate: 3 },
      drawTimes: { shadow: 1, lit: 2 },
      timestamps: true,
      frameMs: 1,
      jsMs: 1,
      rebuilds: 1,
      adapter: 'test',
      surface: { shown: 'catmull-clark' },
      instanced: { counts: countsFromRecords(records, patterns), setting: 'static level 4' },
    };
    const html = renderStats(input);
    expect(html).toContain('instanced, static level 4');
    expect(html).toContain('L1: 5 · L4: 3 · L16: 2');
    expect(html).toContain('draw ms (evaluates)');
    expect(html).toContain('<b>Phong</b>');
    expect(html).not.toContain('tessellation ms');
    expect(html).not.toContain('buffers');
  });
});
