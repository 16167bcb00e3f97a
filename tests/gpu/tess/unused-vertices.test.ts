// withoutUnusedVertices: what the tessellate CLI writes when the cage has vertices no face uses
// (they go through the pipeline, numbered as in the cage). No GPU: a readback made by hand.
import { describe, expect, it } from 'vitest';
import type { MeshReadback } from '../../../src/gpu/device/readback.ts';
import { type HeadlessResult, withoutUnusedVertices } from '../../../src/gpu/tess/headless.ts';

function result(vertexCount: number, indices: number[]): HeadlessResult {
  const out: MeshReadback = {
    vertexCount,
    triangleCount: indices.length / 3,
    scale: 1,
    budgetCandidate: 0,
    positions: Float32Array.from({ length: 3 * vertexCount + 6 }, (_, i) => i), // capacity past the count
    normals: Float32Array.from({ length: 3 * vertexCount }, (_, i) => -i),
    bary: Uint32Array.from({ length: vertexCount }, (_, v) => 100 + v),
    srcTri: Uint32Array.from({ length: vertexCount }, (_, v) => 200 + v),
    indices: Uint32Array.from(indices),
  };
  return { out } as HeadlessResult;
}

describe('the unused vertices of the output', () => {
  it('are left out, the rest renumbered in order with their data', () => {
    const { r, kept } = withoutUnusedVertices(result(5, [0, 2, 3, 3, 2, 4]));
    expect(Array.from(kept ?? [])).toEqual([0, 2, 3, 4]);
    expect(r.out.vertexCount).toBe(4);
    expect(Array.from(r.out.indices)).toEqual([0, 1, 2, 2, 1, 3]);
    expect(Array.from(r.out.positions)).toEqual([0, 1, 2, 6, 7, 8, 9, 10, 11, 12, 13, 14]);
    expect(Array.from(r.out.normals)).toEqual([-0, -1, -2, -6, -7, -8, -9, -10, -11, -12, -13, -14]);
    expect(Array.from(r.out.bary)).toEqual([100, 102, 103, 104]);
    expect(Array.from(r.out.srcTri)).toEqual([200, 202, 203, 204]);
  });

  it('leave the result as it is when every vertex is used', () => {
    const all = result(3, [0, 1, 2]);
    expect(withoutUnusedVertices(all)).toEqual({ r: all, kept: null });
  });
});
