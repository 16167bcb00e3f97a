/**
 * The Phong surface's α per edge (src/gpu/surface/phong.ts has the surface in Bézier form: the
 * control point of edge i → j is b_ij = (p_i + p_j)/2 + (α/2)·((e·n_j) n_j − (e·n_i) n_i), so α may
 * differ from edge to edge and the surface stays watertight).
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
import { PHONG_ALPHA } from '../contract/constants.ts';

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
