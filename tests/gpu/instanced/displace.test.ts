/**
 * The instanced tessellator's displacement without a GPU (src/gpu/instanced/displace-vertex.ts): the
 * seam rule's CPU twin (ownerPoint) sends both patches' copies of every boundary point of every
 * shared cage edge to the SAME (triangle, weights) at every pair of levels, so the GPU evaluates
 * one function of one set of integers there; and the module text: wgsl/tess/displace.wgsl renamed
 * onto the lender's buffers (one rename list with the Catmull-Clark evaluator), the lender's
 * bindings where each surface has room for them.
 */
import { INST_SURFACE_GROUP } from '../../../src/gpu/instanced/buffer-layouts.ts';
import { describe, expect, it } from 'vitest';
import { load } from '../../support/instanced-checks.ts';
import { patchDomain, patchEdgeIds, patchCanonical } from '../../../src/gpu/instanced/prepare-patches.ts';
import { patchTriangle } from '../../../src/gpu/instanced/cpu-twin.ts';
import { instancedDisplaceWgsl, ownerPoint } from '../../../src/gpu/instanced/displace-vertex.ts';
import { renameBorrowed } from '../../../src/gpu/instanced/surface-cc.ts';
import { edgePoint } from '../../../src/pattern/pow2.ts';
import displaceWgsl from '../../../wgsl/tess/displace.wgsl?raw';
import creature from '../../../public/models/creature.obj?raw';
import pawn from '../../../public/models/pawn.obj?raw';

describe('instanced displacement: the seam rule on the CPU', () => {
  for (const [name, text] of [
    ['creature', creature],
    ['pawn', pawn],
  ] as const) {
    it(`${name}: both sides of every shared cage edge, at every level pair, evaluate each edge point at one owner (triangle, weights)`, () => {
      const m = load(text);
      // Per edge and canonical parameter (in 64ths): the owner point the first side gave.
      const seen = new Map<string, string>();
      let pairs = 0;
      for (let p = 0; p < m.patchCount; p++) {
        const dom = patchDomain(m, p),
          ids = patchEdgeIds(m, p),
          can = patchCanonical(m, p);
        ids.forEach((e, k) => {
          for (const P of [1, 2, 4, 8, 16, 32, 64]) {
            for (let s = 0; s <= P; s++) {
              const [i, j] = edgePoint(dom, P, k, s);
              const pt = patchTriangle(m, p, P, i, j);
              const o = ownerPoint(m.prepared, pt.t, pt.w);
              // The owner's weights are the same point: its corners' cage vertices, weighted.
              expect(o.w[0] + o.w[1] + o.w[2]).toBe(65536);
              const at = (t: number, w: readonly number[]) =>
                [0, 1, 2]
                  .filter((c) => w[c] > 0)
                  .map((c) => `${m.prepared.triVerts[3 * t + c]}:${w[c]}`)
                  .sort()
                  .join(' ');
              expect(at(o.t, o.w)).toBe(at(pt.t, pt.w));
              const key = `${e} ${((can[k] ? s : P - s) * 64) / P}`;
              const value = `${o.t} ${o.w.join(' ')}`;
              const before = seen.get(key);
              if (before === undefined) seen.set(key, value);
              else {
                expect(value).toBe(before);
                pairs++;
              }
            }
          }
        });
      }
      expect(pairs).toBeGreaterThan(m.edgeCount);
    });
  }
});

describe('instanced displacement: the module text', () => {
  it('wgsl/tess/displace.wgsl reads the lender (params, staticBuf, cageBuf renamed as whole identifiers); a name no longer there is reported', () => {
    const code = renameBorrowed(displaceWgsl, ['params', 'staticBuf', 'cageBuf']);
    expect(code).not.toMatch(/\b(params|staticBuf|cageBuf)\b/);
    expect(code).toMatch(/\bccParams\.dispScale\b/);
    expect(() => renameBorrowed('fn f() {}', ['params'])).toThrow(/no longer uses 'params'/);
  });

  it("the lender's buffers: group 3 under the exact surface's borrowed names, each at its own binding (none renumbered, none declared by the displacement text)", () => {
    for (const kind of ['evalSurface', 'acc', 'lent-limit'] as const) expect(instancedDisplaceWgsl(kind)).not.toMatch(/@binding/);
    expect(INST_SURFACE_GROUP.group).toBe(3);
    const b = INST_SURFACE_GROUP.binding;
    expect(new Set(Object.values(b)).size).toBe(Object.keys(b).length);
    // An ACC surface with a lender binds all five at once: its patches and points beside the lender's three.
    const acc = INST_SURFACE_GROUP.wgsl(['accPatches', 'accPoints', 'ccParams', 'ccStatic', 'ccCage']);
    expect([...acc.matchAll(/@group\(3\) @binding\((\d+)\)/g)].map((x) => Number(x[1]))).toEqual([0, 1, 2, 4, 5]);
    expect(instancedDisplaceWgsl('acc')).toMatch(/fn triSurface\(/);
  });
});
