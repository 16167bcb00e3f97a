/**
 * Phong tessellation (Boubekeur & Alexa 2008) on the CPU, in double precision: the reference
 * that wgsl/surface/phong.wgsl evalSurface is held to, the α of each edge (phongTriAlphas), and
 * the factor rule's bulge term over the surface (phongEdgeBulges: what wgsl/tess/factor-bulge.wgsl
 * computes on the Phong surface; phongEdgeFactors: the whole rule per edge).
 *
 * THE SURFACE. Projecting the linear point onto the three corners' tangent planes and
 * interpolating the projections is the quadratic Bézier triangle with the corners as its corner
 * control points and, on edge i → j (e = p_j − p_i), the control point
 *     b_ij = (p_i + p_j)/2 + (α/2)·((e·n_j) n_j − (e·n_i) n_i)
 * (α = 1 is Phong's projection, α = 0 the flat triangle; Boubekeur & Alexa blend with α = 3/4).
 * b_ij depends on the edge alone, so α may differ from edge to edge and the two triangles of an
 * edge still agree on it: the surface stays watertight.
 *
 * The α of each edge is phong-alpha.ts's rule (a corner Jacobian of at least PHONG_MIN_JACOBIAN).
 */
import { BULGE_OFF_SCREEN, bulgeFactor, edgeFactor, type FactorRule, type Vec3 } from '../tess/factors.ts';
import { ONE } from '../../pattern/fixed.ts';
import type { PreparedMesh } from '../tess/prepare.ts';

/** The control point of edge i → j (the header's b_ij). */
function edgeControl(pi: number[], ni: number[], pj: number[], nj: number[], alpha: number): number[] {
  const e = [pj[0] - pi[0], pj[1] - pi[1], pj[2] - pi[2]];
  const di = e[0] * ni[0] + e[1] * ni[1] + e[2] * ni[2],
    dj = e[0] * nj[0] + e[1] * nj[1] + e[2] * nj[2];
  return [0, 1, 2].map((c) => 0.5 * (pi[c] + pj[c]) + 0.5 * alpha * (dj * nj[c] - di * ni[c]));
}

/** The surface point at barycentrics w of triangle t, and the shading normal (the vertex normals
 * interpolated, as Phong tessellation shades). */
export function phongPoint(mesh: PreparedMesh, t: number, w: readonly [number, number, number]): { pos: number[]; normal: number[] } {
  const P = mesh.positions,
    N = mesh.normals;
  const v = [mesh.triVerts[3 * t], mesh.triVerts[3 * t + 1], mesh.triVerts[3 * t + 2]];
  const p = v.map((x) => [P[3 * x], P[3 * x + 1], P[3 * x + 2]]);
  const nv = v.map((x) => [N[3 * x], N[3 * x + 1], N[3 * x + 2]]);
  const b = [0, 1, 2].map((i) => edgeControl(p[i], nv[i], p[(i + 1) % 3], nv[(i + 1) % 3], mesh.triPhongAlpha[3 * t + i]));
  const pos = [0, 1, 2].map(
    (c) =>
      w[0] * w[0] * p[0][c] +
      w[1] * w[1] * p[1][c] +
      w[2] * w[2] * p[2][c] +
      2 * (w[0] * w[1] * b[0][c] + w[1] * w[2] * b[1][c] + w[2] * w[0] * b[2][c]),
  );
  const n = [0, 1, 2].map((c) => w[0] * nv[0][c] + w[1] * nv[1][c] + w[2] * nv[2][c]);
  const len = Math.hypot(n[0], n[1], n[2]);
  return { pos, normal: len > 0 ? n.map((x) => x / len) : nv[0] };
}

/** Each edge's bulge term (src/gpu/tess/factors.ts bulgeFactor) on the Phong surface: the larger of
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

/** Every edge's factor under `rule` on the Phong surface (src/gpu/tess/factors.ts edgeFactor with its
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
