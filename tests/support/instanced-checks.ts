/**
 * Checks of the instanced tessellator's headless output shared by its GPU tests
 * (tests/gpu/instanced/instanced.gpu.test.ts: Phong and ACC; tests/gpu/instanced/surface-cc.gpu.test.ts: the exact
 * Catmull-Clark surface): the layout, the CPU snap, no flipped triangle, and the crack check
 * (along every shared cage edge the snapped points of both sides pair up; the largest gap).
 */
import { expect } from 'vitest';
import { mat4 } from 'gl-matrix';
import { loadCage } from '../../src/mesh/index.ts';
import { prepareMesh } from '../../src/gpu/tess/prepare.ts';
import { phongPoint } from '../../src/gpu/surface/phong.ts';
import type { InstancedTessellator } from '../../src/gpu/instanced/instanced.ts';
import {
  prepareInstanced,
  patchDomain,
  patchEdgeIds,
  patchCanonical,
  type InstancedMesh,
} from '../../src/gpu/instanced/prepare-patches.ts';
import { patchTriangle, snapPatchVertex } from '../../src/gpu/instanced/cpu-twin.ts';
import type { HeadlessInstanced } from '../../src/gpu/instanced/headless-output.ts';
import { vertexEdges } from '../../src/pattern/pow2.ts';

export function rng(seed: number) {
  return () => (seed = (Math.imul(seed, 1103515245) + 12345) >>> 0) / 2 ** 32;
}
export function randomLevels(n: number, max: number, seed: number): Uint32Array {
  const r = rng(seed);
  const choices = [1, 2, 4, 8, 16, 32, 64].filter((l) => l <= max);
  return Uint32Array.from({ length: n }, () => choices[Math.floor(r() * choices.length)]);
}

export function load(text: string): InstancedMesh {
  const cage = loadCage(text).cage;
  return prepareInstanced(cage, prepareMesh(cage));
}

export function camera(m: InstancedMesh, distance: number): { viewProj: Float32Array; eye: [number, number, number] } {
  const pr = m.prepared;
  const c = [0, 1, 2].map((i) => (pr.bboxMin[i] + pr.bboxMax[i]) / 2) as [number, number, number];
  const eye: [number, number, number] = [c[0] + 0.4 * distance, c[1] + 0.5 * distance, c[2] + distance];
  const view = mat4.lookAt(mat4.create(), eye, c, [0, 1, 0]);
  const proj = mat4.perspectiveZO(mat4.create(), Math.PI / 4, 1, 0.01 * pr.size, 100 * pr.size);
  return { viewProj: mat4.multiply(mat4.create(), proj, view) as Float32Array, eye };
}

/**
 * Every check of the headless output against the CPU; returns the largest gap across an edge
 * (in units of the model's size) and the largest position error.
 */
export function checkHeadless(
  m: InstancedMesh,
  out: HeadlessInstanced,
  tess: InstancedTessellator,
  phong = true,
): { gap: number; posError: number; edgesChecked: number } {
  const size = m.prepared.size;
  const { edgeLevels, patchLevels } = out;
  // Edge level = min over its patches' levels (modes static, per-patch) or ≤ each patch's level
  // (dynamic): never above a patch's level.
  for (let p = 0; p < m.patchCount; p++) for (const e of patchEdgeIds(m, p)) expect(edgeLevels[e]).toBeLessThanOrEqual(patchLevels[p]);

  // Walk the output as the GPU laid it out: bucket by bucket, instance by instance, the whole
  // pattern of each; the instance order within a bucket is the atomics' order, so each block's
  // patch is read from the output and checked to be in that bucket.
  const seen = new Uint8Array(m.patchCount);
  // Per edge and side (patch): canonical parameter → position.
  const sides = new Map<number, Map<number, Map<number, number[]>>>();
  let v0 = 0,
    t0 = 0,
    posError = 0;
  tess.patterns.entries.forEach((entry, b) => {
    const P = entry.level;
    const pattern = tess.patterns.ij.subarray(entry.baseVertex, entry.baseVertex + entry.vertexCount);
    const local = tess.patterns.indices.subarray(entry.firstIndex, entry.firstIndex + entry.indexCount);
    for (let inst = 0; inst < out.counts[b]; inst++) {
      const p = out.patch[v0];
      expect(seen[p]).toBe(0);
      seen[p] = 1;
      expect(patchDomain(m, p)).toBe(entry.domain);
      expect(patchLevels[p]).toBe(P);
      const snappedIJ: [number, number][] = [];
      for (let k = 0; k < entry.vertexCount; k++) {
        const v = v0 + k;
        expect(out.patch[v]).toBe(p);
        const [i, j] = snapPatchVertex(m, p, P, pattern[k] & 0xffff, pattern[k] >>> 16, edgeLevels);
        snappedIJ.push([i, j]);
        // The GPU's snapped parameter, exactly.
        expect([out.uv[2 * v], out.uv[2 * v + 1]]).toEqual([i / P, j / P]);
        const { t, w } = patchTriangle(m, p, P, i, j);
        const ref = phong ? phongPoint(m.prepared, t, [w[0] / 65536, w[1] / 65536, w[2] / 65536]) : null;
        for (let c = 0; c < 3; c++) {
          const x = out.positions[3 * v + c],
            n = out.normals[3 * v + c];
          if (!Number.isFinite(x) || !Number.isFinite(n)) throw new Error(`NaN or infinity at vertex ${v}`);
          if (ref) posError = Math.max(posError, Math.abs(x - ref.pos[c]) / size);
        }
        // Boundary points, by edge, side and canonical parameter.
        const dom = patchDomain(m, p),
          can = patchCanonical(m, p),
          ids = patchEdgeIds(m, p);
        for (const { edge, t: te } of vertexEdges(dom, P, i, j)) {
          const e = ids[edge];
          const cpar = can[edge] ? te / P : 1 - te / P;
          let bySide = sides.get(e);
          if (!bySide) sides.set(e, (bySide = new Map()));
          let pts = bySide.get(p);
          if (!pts) bySide.set(p, (pts = new Map()));
          const pos = [out.positions[3 * v], out.positions[3 * v + 1], out.positions[3 * v + 2]];
          const prev = pts.get(cpar);
          // A side evaluates the same parameter to the same bits, however many fine vertices
          // snapped onto it.
          if (prev) expect(pos).toEqual(prev);
          else pts.set(cpar, pos);
        }
      }
      // Triangles: the pattern's, offset to this block; none flipped in the snapped (u, v).
      const nt = entry.indexCount / 3;
      for (let q = 0; q < nt; q++) {
        const tri = [0, 1, 2].map((c) => out.indices[3 * (t0 + q) + c]);
        expect(tri).toEqual([0, 1, 2].map((c) => v0 + local[3 * q + c]));
        const [a, bb, c] = tri.map((x) => snappedIJ[x - v0]);
        const area2 = (bb[0] - a[0]) * (c[1] - a[1]) - (bb[1] - a[1]) * (c[0] - a[0]);
        expect(area2).toBeGreaterThanOrEqual(0);
      }
      v0 += entry.vertexCount;
      t0 += nt;
    }
  });
  expect(v0).toBe(out.vertexCount);
  expect(t0).toBe(out.triangleCount);
  expect(seen.every((x) => x === 1)).toBe(true);

  // Cracks: along every edge shared by two patches, both sides hold exactly the points
  // {j / L_e} and pair up one to one; report the largest distance between partners.
  let gap = 0,
    edgesChecked = 0;
  for (const [e, bySide] of sides) {
    const L = edgeLevels[e];
    const expected = Array.from({ length: L + 1 }, (_, j) => j / L);
    for (const pts of bySide.values()) expect([...pts.keys()].sort((x, y) => x - y)).toEqual(expected);
    if (bySide.size < 2) continue;
    const [a, b] = [...bySide.values()];
    for (const c of expected) {
      const pa = a.get(c)!,
        pb = b.get(c)!;
      gap = Math.max(gap, Math.hypot(pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]) / size);
    }
    edgesChecked++;
  }
  return { gap, posError, edgesChecked };
}
