/**
 * Phong tessellation (Boubekeur & Alexa 2008) on the CPU, in double precision: the reference
 * that wgsl/surface-phong.wgsl evalSurface is held to, and the factor rule's bulge term over it
 * (phongEdgeBulges: what wgsl/factor-bulge.wgsl computes on the Phong surface; phongEdgeFactors:
 * the whole rule per edge).
 */
import { BULGE_OFF_SCREEN, bulgeFactor, edgeFactor, type FactorRule, PHONG_ALPHA, type Vec3 } from './factors.ts';
import { ONE } from '../pattern/fixed.ts';
import type { PreparedMesh } from './prepare.ts';

export function phongPoint(mesh: PreparedMesh, t: number, w: readonly [number, number, number]): { pos: number[]; normal: number[] } {
  const P = mesh.positions,
    N = mesh.normals;
  const v = [mesh.triVerts[3 * t], mesh.triVerts[3 * t + 1], mesh.triVerts[3 * t + 2]];
  const p = [0, 1, 2].map((c) => w[0] * P[3 * v[0] + c] + w[1] * P[3 * v[1] + c] + w[2] * P[3 * v[2] + c]);
  const phong = [0, 0, 0];
  const n = [0, 0, 0];
  for (let i = 0; i < 3; i++) {
    const pi = [P[3 * v[i]], P[3 * v[i] + 1], P[3 * v[i] + 2]];
    const ni = [N[3 * v[i]], N[3 * v[i] + 1], N[3 * v[i] + 2]];
    const d = (p[0] - pi[0]) * ni[0] + (p[1] - pi[1]) * ni[1] + (p[2] - pi[2]) * ni[2];
    for (let c = 0; c < 3; c++) {
      phong[c] += w[i] * (p[c] - d * ni[c]);
      n[c] += w[i] * ni[c];
    }
  }
  const len = Math.hypot(n[0], n[1], n[2]);
  return {
    pos: p.map((x, c) => x + PHONG_ALPHA * (phong[c] - x)),
    normal: len > 0 ? n.map((x) => x / len) : [N[3 * v[0]], N[3 * v[0] + 1], N[3 * v[0] + 2]],
  };
}

/** Each edge's bulge term (src/gpu/factors.ts bulgeFactor) on the Phong surface: the larger of
 * its two triangles' (BULGE_OFF_SCREEN, none, in fixed mode). */
export function phongEdgeBulges(mesh: PreparedMesh, rule: FactorRule): Float64Array {
  const bulge = new Float64Array(mesh.edgeCount).fill(BULGE_OFF_SCREEN);
  if (rule.mode !== 'adaptive') return bulge;
  const P = mesh.positions;
  for (let t = 0; t < mesh.triangleCount; t++) {
    const corners = [0, 1, 2].map((i) => {
      const v = mesh.triVerts[3 * t + i];
      return [P[3 * v], P[3 * v + 1], P[3 * v + 2]];
    }) as unknown as [Vec3, Vec3, Vec3];
    const k = bulgeFactor(corners, (w) => phongPoint(mesh, t, [w[0] / ONE, w[1] / ONE, w[2] / ONE]), rule);
    for (let i = 0; i < 3; i++) {
      const e = mesh.triEdges[3 * t + i];
      bulge[e] = Math.max(bulge[e], k);
    }
  }
  return bulge;
}

/** Every edge's factor under `rule` on the Phong surface (src/gpu/factors.ts edgeFactor with its
 * triangles' bulge term), in double precision: what the GPU's factor pass computes for Phong. */
export function phongEdgeFactors(mesh: PreparedMesh, rule: FactorRule): Float64Array {
  const P = mesh.positions,
    N = mesh.normals;
  const vec = (a: ArrayLike<number>, i: number): Vec3 => [a[3 * i], a[3 * i + 1], a[3 * i + 2]];
  const bulge = phongEdgeBulges(mesh, rule);
  const f = new Float64Array(mesh.edgeCount);
  for (let e = 0; e < mesh.edgeCount; e++) {
    const a = mesh.edgeVerts[2 * e],
      b = mesh.edgeVerts[2 * e + 1];
    f[e] = edgeFactor(vec(P, a), vec(P, b), vec(N, a), vec(N, b), rule, bulge[e]);
  }
  return f;
}
