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
 * α PER EDGE. At corner i the surface's Jacobian, against the flat triangle's, is 1 − α·sin²θ_i,
 * θ_i the angle between the vertex normal and the face normal: a vertex normal that lies nearly
 * in a face's plane (between the creature's legs, cos θ = 0.11) squeezes the pattern beside that
 * corner to a quarter of its area, and its slivers turn over at any factor (issue 13: six
 * folded triangles of 1.6 million over tests/gpu/tess/no-folds.test.ts's views, at factors 6 to 17). So
 * each triangle asks for α ≤ (1 − PHONG_MIN_JACOBIAN)/sin²θ_i at every corner, and for α = 0 where
 * a corner's vertex normal points away from the face (cos θ_i ≤ 0: the vertex's tangent plane
 * is turned over against the face there), and each edge takes PHONG_ALPHA or the least that
 * its triangles ask, whichever is lower. Measured (tests/gpu/tess/no-folds.test.ts's header): folds 0 on
 * every project model over 96 views (the creature 20 before), 411 of the creature's 1,692 edges
 * lowered (56 to 0), its surface moved by up to 0.64 % of its size; the boxes, gear and pawn
 * lowered to 0.645, 0.573 and 0.551 at least; the sphere, torus and sheet unchanged.
 */
import { BULGE_OFF_SCREEN, bulgeFactor, edgeFactor, type FactorRule, PHONG_ALPHA, type Vec3 } from '../tess/factors.ts';
import { ONE } from '../../pattern/fixed.ts';
import type { PreparedMesh } from '../tess/prepare.ts';

/** The least Jacobian of the Phong surface at a triangle's corner, against the flat triangle's. */
export const PHONG_MIN_JACOBIAN = 0.45;

/**
 * The α of each triangle's three edges (edge i runs from corner i to corner i + 1), 3 per
 * triangle: the header's rule over the given positions and unit vertex normals (xyz each), so it
 * is recomputed when an animated cage moves. Linear in the triangles.
 */
export function phongTriAlphas(
  mesh: { triangleCount: number; edgeCount: number; triVerts: ArrayLike<number>; triEdges: ArrayLike<number> },
  positions: ArrayLike<number>,
  normals: ArrayLike<number>,
): Float32Array {
  const P = positions,
    N = normals;
  const edgeAlpha = new Float64Array(mesh.edgeCount).fill(PHONG_ALPHA);
  for (let t = 0; t < mesh.triangleCount; t++) {
    const v = [mesh.triVerts[3 * t], mesh.triVerts[3 * t + 1], mesh.triVerts[3 * t + 2]];
    const a = [0, 1, 2].map((c) => P[3 * v[1] + c] - P[3 * v[0] + c]);
    const b = [0, 1, 2].map((c) => P[3 * v[2] + c] - P[3 * v[0] + c]);
    const f = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    const len = Math.hypot(f[0], f[1], f[2]);
    if (!(len > 0)) continue; // a degenerate triangle asks nothing
    let ask = PHONG_ALPHA;
    for (const x of v) {
      const cos = (f[0] * N[3 * x] + f[1] * N[3 * x + 1] + f[2] * N[3 * x + 2]) / len;
      const sin2 = 1 - Math.min(1, cos * cos);
      ask = Math.min(ask, cos <= 0 ? 0 : (1 - PHONG_MIN_JACOBIAN) / sin2);
    }
    for (let i = 0; i < 3; i++) {
      const e = mesh.triEdges[3 * t + i];
      edgeAlpha[e] = Math.min(edgeAlpha[e], ask);
    }
  }
  const out = new Float32Array(3 * mesh.triangleCount);
  for (let k = 0; k < out.length; k++) out[k] = edgeAlpha[mesh.triEdges[k]];
  return out;
}

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
