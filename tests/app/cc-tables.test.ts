// The exact surface's CPU preparation as the page caches it (src/app/cc-tables.ts): a cage from
// OFF_THREAD_FACES faces on goes to a worker in the browser (here, in Node, without workers, the
// same function runs in place): the prepared mesh and the tables it hands back are the ones the
// tessellator would have made itself, once per cage; a refused cage rejects with its reason.
import { describe, expect, it } from 'vitest';
import { CcTableCache, OFF_THREAD_FACES } from '../../src/app/cc-tables.ts';
import { loadCage } from '../../src/mesh/index.ts';
import { prepareMesh } from '../../src/gpu/tess/prepare.ts';
import { buildCatmullClark } from '../../src/gpu/cc/build.ts';

function grid(n: number): string {
  const lines: string[] = [];
  for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) lines.push(`v ${i} ${j} ${Math.sin(i) * 0.1}`);
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++) {
      const a = j * (n + 1) + i + 1;
      lines.push(`f ${a} ${a + 1} ${a + n + 2} ${a + n + 1}`);
    }
  return lines.join('\n');
}

describe('CcTableCache', () => {
  it('prepares a cage past OFF_THREAD_FACES once: the mesh and tables the tessellator would make', async () => {
    const n = Math.ceil(Math.sqrt(OFF_THREAD_FACES)) + 1;
    const { cage } = loadCage(grid(n));
    expect(n * n).toBeGreaterThanOrEqual(OFF_THREAD_FACES);
    const cache = new CcTableCache();
    const first = cache.get(cage);
    expect(cache.get(cage)).toBe(first);
    const t = await first;
    expect(cache.has(cage)).toBe(true);
    const mesh = prepareMesh(cage);
    expect(t.mesh.triangleCount).toBe(2 * n * n);
    // Byte for byte (toEqual walks large arrays element by element, slowly).
    const same = (a: ArrayBufferView, b: ArrayBufferView) =>
      Buffer.from(a.buffer, a.byteOffset, a.byteLength).equals(Buffer.from(b.buffer, b.byteOffset, b.byteLength));
    expect(same(t.mesh.triVerts, mesh.triVerts)).toBe(true);
    expect(same(t.mesh.edgeOwner, mesh.edgeOwner)).toBe(true);
    expect(same(t.data.words, buildCatmullClark(cage, mesh).words)).toBe(true);
    expect(t.ms).toBeGreaterThan(0);
  });

  it('a cage the preparation refuses rejects with a message fit to show', async () => {
    // A cube with a crease of sharpness 8 under Chaikin's rule: its decay stays in uniform levels
    // (semi-sharp creases under uniform creasing decay inside the slice kernel), more than the
    // build makes.
    const cube = ['v -1 -1 -1', 'v 1 -1 -1', 'v 1 1 -1', 'v -1 1 -1', 'v -1 -1 1', 'v 1 -1 1', 'v 1 1 1', 'v -1 1 1'];
    const faces = ['f 1 4 3 2', 'f 5 6 7 8', 'f 1 2 6 5', 'f 2 3 7 6', 'f 3 4 8 7', 'f 4 1 5 8'];
    const { cage } = loadCage([...cube, ...faces, 't crease 2/1/0 4 5 8', 't creasemethod 0/0/1 chaikin'].join('\n'));
    await expect(new CcTableCache().get(cage)).rejects.toThrow(/more than 6 levels of refinement/);
  });
});
