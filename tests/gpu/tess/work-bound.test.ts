// workBytesAtLeast, the tessellate CLI's check of a cage against the binding limit before its
// preparation, must never exceed the work arena the tessellator then sizes, or a cage that fits
// would be refused.
import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { MAX_FACTOR } from '../../../src/gpu/contract/constants.ts';
import { TESS_WORK } from '../../../src/gpu/contract/tess.ts';
import { workBytesAtLeast } from '../../../src/gpu/tess/arenas.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { loadCage } from '../../../src/mesh/index.ts';

describe('the work arena bound from face sizes', () => {
  it("is at most the arena's size on every project model, and within a few percent of it", () => {
    for (const file of readdirSync('public/models').filter((f) => f.endsWith('.obj'))) {
      const { cage } = loadCage(readFileSync(`public/models/${file}`, 'utf8'));
      const mesh = prepareMesh(cage);
      const sizes = { edges: mesh.edgeCount, triangles: mesh.triangleCount, maxFactor: MAX_FACTOR } as Parameters<
        typeof TESS_WORK.layout
      >[0];
      const exact = 4 * TESS_WORK.layout(sizes).words;
      const least = workBytesAtLeast(cage, MAX_FACTOR);
      expect(least, file).toBeLessThanOrEqual(exact);
      expect(least / exact, file).toBeGreaterThan(0.9);
    }
  });
});
