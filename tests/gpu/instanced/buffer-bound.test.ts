// instancedBytesAtLeast, the tessellate CLI's check of a cage against the binding limit before the
// instanced tessellator's preparation: never over the buffers the tessellator then sizes (or a cage
// that fits would be refused), close to them, and a refusal the CLI's boundary reports as exit 2.
import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { describeFailure } from '../../../src/cli/boundary.ts';
import { INST_STATIC, INST_WORK } from '../../../src/gpu/instanced/buffer-layouts.ts';
import { instancedBytesAtLeast, prepareInstanced, refuseInstancedOverLimit } from '../../../src/gpu/instanced/prepare-patches.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { LimitError } from '../../../src/mesh/errors.ts';
import { loadCage } from '../../../src/mesh/index.ts';
import { packPatterns, POW2_LEVELS } from '../../../src/pattern/pow2.ts';

const models = readdirSync('public/models')
  .filter((f) => f.endsWith('.obj'))
  .map((file) => ({ file, cage: loadCage(readFileSync(`public/models/${file}`, 'utf8')).cage }));
const patterns = packPatterns();

describe("the instanced tessellator's buffer bounds from face sizes", () => {
  it('are at most the buffers prepareInstanced and the headless output size, and within a few percent of them', () => {
    for (const { file, cage } of models) {
      const m = prepareInstanced(cage, prepareMesh(cage));
      const staticBytes =
        4 *
        INST_STATIC.layout({
          triangles: m.prepared.triangleCount,
          patches: m.patchCount,
          edges: m.edgeCount,
          patternIJWords: patterns.ij.length,
          patternIndices: patterns.indices.length,
        }).words;
      const workBytes = 4 * INST_WORK.layout({ patches: m.patchCount, edges: m.edgeCount }).words;
      const least = instancedBytesAtLeast(cage);
      expect(least.static, file).toBeLessThanOrEqual(staticBytes);
      expect(least.static / staticBytes, file).toBeGreaterThan(0.9);
      expect(least.work, file).toBeLessThanOrEqual(workBytes);
      expect(least.work / workBytes, file).toBeGreaterThan(0.9);
      expect(least.output, file).toBe(0);
      // At a static level every patch draws its domain's pattern at that level: the headless
      // output's size (instanced.ts headless: 9 words a vertex, 3 a triangle) exactly.
      for (const [k, level] of POW2_LEVELS.entries()) {
        const quad = patterns.entries[k];
        const tri = patterns.entries[POW2_LEVELS.length + k];
        const words = m.quadCount * (9 * quad.vertexCount + quad.indexCount) + m.triCount * (9 * tri.vertexCount + tri.indexCount);
        expect(instancedBytesAtLeast(cage, level).output, `${file} --level ${level}`).toBe(4 * words);
      }
    }
  });

  it('refuse a cage over the binding limit with a LimitError, which the CLI reports as bad input', () => {
    const { cage } = models.find((m) => m.file === 'creature.obj')!;
    const GiB = 2 ** 30;
    expect(() => refuseInstancedOverLimit(cage, GiB, 1)).not.toThrow();
    let refusal: unknown;
    try {
      refuseInstancedOverLimit(cage, instancedBytesAtLeast(cage, 64).output - 1, 64);
    } catch (e) {
      refusal = e;
    }
    expect(refusal).toBeInstanceOf(LimitError);
    expect((refusal as Error).message).toMatch(
      /faces need at least .* MiB for the instanced tessellator's output at --level 64, .*lower --level/,
    );
    expect(() => refuseInstancedOverLimit(cage, 1024)).toThrow(/patch records, more than this device's 0\.0 MiB binding limit/);
    expect(describeFailure('tessellate', refusal, false).code).toBe(2);
  });
});
