/**
 * The instanced tessellator's CPU side (src/gpu/instanced/prepare-patches.ts, cpu-twin.ts), no GPU: patches and edges of the
 * project's cages, the level rule (an edge at the minimum of its patches), and the snap across
 * whole meshes: along every shared edge both patches, at their own pattern levels, land on
 * exactly {j / L_e}. (tests/gpu/instanced/instanced.gpu.test.ts holds the GPU to these same functions.)
 */
import { describe, it, expect } from 'vitest';
import { loadCage } from '../../../src/mesh/index.ts';
import { prepareMesh } from '../../../src/gpu/tess/prepare.ts';
import { InstancedTessellator } from '../../../src/gpu/instanced/instanced.ts';
import { PATCH_WORDS } from '../../../src/gpu/instanced/buffer-layouts.ts';
import { prepareInstanced, patchDomain, patchEdgeIds, patchCanonical } from '../../../src/gpu/instanced/prepare-patches.ts';
import { cpuLevels, snapPatchVertex, patchTriangle } from '../../../src/gpu/instanced/cpu-twin.ts';
import { pow2Pattern, vertexEdges } from '../../../src/pattern/pow2.ts';
import creature from '../../../public/models/creature.obj?raw';
import gear from '../../../public/models/gear.obj?raw';
import icosphere from '../../../public/models/icosphere.obj?raw';
import sheet from '../../../public/models/sheet.obj?raw';

const models: [string, string][] = [
  ['creature', creature],
  ['gear', gear],
  ['icosphere', icosphere],
  ['sheet', sheet],
];

describe('instanced patches, levels and snap on the CPU', () => {
  it("a cage whose boundary mode 'none' makes holes: one patch per face the prepared mesh keeps (was an internal error)", () => {
    // A 3 × 3 grid of quads: under 'none' every face at the boundary has no surface; the centre one stays.
    const v: string[] = [];
    for (let j = 0; j < 4; j++) for (let i = 0; i < 4; i++) v.push(`v ${i} ${j} 0`);
    const f: string[] = [];
    for (let j = 0; j < 3; j++)
      for (let i = 0; i < 3; i++) {
        const a = 4 * j + i + 1;
        f.push(`f ${a} ${a + 1} ${a + 5} ${a + 4}`);
      }
    const cage = loadCage([...v, ...f, 't interpolateboundary 1/0/0 0', ''].join('\n')).cage;
    const prepared = prepareMesh(cage);
    expect(new Set(prepared.triFace).size).toBe(1);
    const m = prepareInstanced(cage, prepared);
    expect(m.patches.length / PATCH_WORDS).toBe(1);
  });
  for (const [name, text] of models) {
    it(`${name}: patches, edges, opposite walks; random levels close every edge`, () => {
      const cage = loadCage(text).cage;
      const prepared = prepareMesh(cage);
      const m = prepareInstanced(cage, prepared);
      // Quads are quad patches; a triangle is one triangle patch, and an n-gon (n ≥ 5) its n
      // triangles round its centre (prepare.ts).
      let quads = 0,
        tris = 0;
      const cageEdges = new Set<string>();
      for (let f = 0; f + 1 < cage.faceOffsets.length; f++) {
        if (cage.holes.includes(f)) continue;
        const s = cage.faceOffsets[f],
          n = cage.faceOffsets[f + 1] - s;
        if (n === 4) quads++;
        else tris += n === 3 ? 1 : n;
        for (let k = 0; k < n; k++) {
          const a = cage.faceIndices[s + k],
            b = cage.faceIndices[s + ((k + 1) % n)];
          cageEdges.add(`${Math.min(a, b)},${Math.max(a, b)}`);
        }
      }
      expect([m.quadCount, m.triCount]).toEqual([quads, tris]);
      // An n-gon (n ≥ 5) adds its n spokes from the centre as edges between its triangle patches.
      let spokes = 0;
      for (let f = 0; f + 1 < cage.faceOffsets.length; f++) {
        const n = cage.faceOffsets[f + 1] - cage.faceOffsets[f];
        if (!cage.holes.includes(f) && n >= 5) spokes += n;
      }
      expect(m.edgeCount).toBe(cageEdges.size + spokes);

      // Each edge: at most two patches, walking it in opposite directions (a consistently
      // oriented cage), so exactly one of them walks it canonically.
      const users = new Map<number, { p: number; canonical: boolean }[]>();
      for (let p = 0; p < m.patchCount; p++) {
        patchEdgeIds(m, p).forEach((e, k) => {
          const list = users.get(e) ?? [];
          list.push({ p, canonical: patchCanonical(m, p)[k] });
          users.set(e, list);
        });
      }
      expect(users.size).toBe(m.edgeCount);
      for (const list of users.values()) {
        expect(list.length).toBeLessThanOrEqual(2);
        if (list.length === 2) expect(list[0].canonical).not.toBe(list[1].canonical);
      }

      // Patch corners map onto the cage triangles' corners.
      for (let p = 0; p < m.patchCount; p++) {
        const quad = patchDomain(m, p) === 'quad';
        const at = quad
          ? [
              [0, 0],
              [1, 0],
              [1, 1],
              [0, 1],
            ]
          : [
              [0, 0],
              [1, 0],
              [0, 1],
            ];
        at.forEach(([i, j], k) => {
          const { t, w } = patchTriangle(m, p, 1, i, j);
          const c = w.indexOf(65536);
          expect(prepared.triVerts[3 * t + c]).toBe(m.corners[4 * p + k]);
        });
        expect(m.patches[PATCH_WORDS * p + 6]).toBe(prepared.triFace[m.patches[PATCH_WORDS * p]]);
      }

      // Random per-patch levels: edge = min of its patches; both sides snap onto {j / L_e}.
      let seed = 99;
      const rand = () => (seed = (Math.imul(seed, 1103515245) + 12345) >>> 0) / 2 ** 32;
      const wanted = Uint32Array.from({ length: m.patchCount }, () => 2 ** Math.floor(rand() * 6));
      const lv = cpuLevels(m, wanted);
      expect(lv.counts.reduce((a, b) => a + b, 0)).toBe(m.patchCount);
      for (const [e, list] of users) expect(lv.edgeLevels[e]).toBe(Math.min(...list.map((u) => wanted[u.p])));
      const sides = new Map<number, Set<number>[]>();
      for (let p = 0; p < m.patchCount; p++) {
        const P = lv.patchLevels[p],
          dom = patchDomain(m, p),
          pat = pow2Pattern(dom, P);
        const ids = patchEdgeIds(m, p),
          can = patchCanonical(m, p);
        const mine = ids.map(() => new Set<number>());
        for (let v = 0; v < pat.ij.length / 2; v++) {
          const [i, j] = snapPatchVertex(m, p, P, pat.ij[2 * v], pat.ij[2 * v + 1], lv.edgeLevels);
          for (const { edge, t } of vertexEdges(dom, P, i, j)) mine[edge].add(can[edge] ? t / P : 1 - t / P);
        }
        ids.forEach((e, k) => sides.set(e, [...(sides.get(e) ?? []), mine[k]]));
      }
      for (const [e, list] of sides) {
        const L = lv.edgeLevels[e];
        const expected = Array.from({ length: L + 1 }, (_, j) => j / L);
        for (const set of list) expect([...set].sort((a, b) => a - b)).toEqual(expected);
      }
    });
  }
});

describe('instanced tessellator: storage buffers per stage', () => {
  // Only the limits are read before the check (no GPU needed): a compatibility-mode device
  // allows few storage buffers in the vertex stage.
  const device = (inVertex: number | undefined, perStage: number) =>
    ({ limits: { maxStorageBuffersInVertexStage: inVertex, maxStorageBuffersPerShaderStage: perStage } }) as unknown as GPUDevice;
  it('refuses a device with too few, with the numbers: Phong 3 in the vertex stage, ACC 5, Catmull-Clark 6; with displacement Phong 5, ACC 7 (8 in compute), Catmull-Clark 6', () => {
    expect(() => new InstancedTessellator(device(2, 8))).toThrow(
      /needs 3 storage buffers in the vertex stage and 4 in compute; this device allows 2 and 8/,
    );
    expect(() => new InstancedTessellator(device(4, 8), { surface: 'acc' })).toThrow(/needs 5 .* and 6 in compute/);
    expect(() => new InstancedTessellator(device(5, 8), { surface: 'lent-limit' })).toThrow(/needs 6 .* and 7 in compute/);
    expect(() => new InstancedTessellator(device(undefined, 6), { surface: 'lent-limit' })).toThrow(/needs 6 .* and 7 in compute/);
    // Displacement: the lender's static and cage arenas (on Catmull-Clark the surface's lender, already bound).
    expect(() => new InstancedTessellator(device(4, 8), { displacement: true })).toThrow(/needs 5 .* and 6 in compute/);
    expect(() => new InstancedTessellator(device(6, 8), { surface: 'acc', displacement: true })).toThrow(/needs 7 .* and 8 in compute/);
    expect(() => new InstancedTessellator(device(undefined, 7), { surface: 'acc', displacement: true })).toThrow(
      /needs 7 .* and 8 in compute/,
    );
    expect(() => new InstancedTessellator(device(5, 8), { surface: 'lent-limit', displacement: true })).toThrow(
      /needs 6 .* and 7 in compute/,
    );
  });
});
