/**
 * Where an output vertex lies on its source cage face, in the CPU reference's addressing
 * (src/subdiv): `f u v` on a quad (corners 0..3 at (0,0), (1,0), (1,1), (0,1)), `f k s t` on
 * sub-face k of a face with n ≠ 4 corners (sub-face k spans corner k (0,0), the midpoint of edge
 * k→k+1 (1,0), the face centre (1,1) and the midpoint of edge k−1→k (0,1)).
 *
 * A quad is split along its 0–2 diagonal (prepare.ts), so its two triangles map linearly:
 * (c0,c1,c2) → (u,v) = (w1 + w2, w2) and (c0,c2,c3) → (w1, w1 + w2). A triangle, and each
 * triangle (centre, k, k + 1) of a face fanned round its centre (n ≥ 5, prepare.ts), maps
 * linearly into the regular n-gon (the centre at its origin), where sub-face k is the kite
 * around corner k and (s, t) inverts the kite's bilinear map. For a triangle this is the closed
 * form k = argmax w, s = 2·w_{k+1} along edge k→k+1 (checked in tests/gpu/tess/factors.test.ts).
 */
import type { PreparedMesh } from './prepare.ts';
import type { Cage } from '../../mesh/types.ts';

export type FaceParam = { face: number; u: number; v: number } | { face: number; k: number; s: number; t: number };

/** Inverse of the bilinear map P(s,t) = (1−s)(1−t)a + s(1−t)b + st·c + (1−s)t·d (2D), by Newton. */
export function inverseBilinear(p: [number, number], a: number[], b: number[], c: number[], d: number[]): [number, number] {
  let s = 0.5,
    t = 0.5;
  for (let i = 0; i < 50; i++) {
    const fx = (1 - s) * (1 - t) * a[0] + s * (1 - t) * b[0] + s * t * c[0] + (1 - s) * t * d[0] - p[0];
    const fy = (1 - s) * (1 - t) * a[1] + s * (1 - t) * b[1] + s * t * c[1] + (1 - s) * t * d[1] - p[1];
    const dsx = (1 - t) * (b[0] - a[0]) + t * (c[0] - d[0]),
      dsy = (1 - t) * (b[1] - a[1]) + t * (c[1] - d[1]);
    const dtx = (1 - s) * (d[0] - a[0]) + s * (c[0] - b[0]),
      dty = (1 - s) * (d[1] - a[1]) + s * (c[1] - b[1]);
    const det = dsx * dty - dsy * dtx;
    if (det === 0) break;
    const ds = (fx * dty - fy * dtx) / det,
      dt = (dsx * fy - dsy * fx) / det;
    s -= ds;
    t -= dt;
    if (Math.abs(ds) + Math.abs(dt) < 1e-15) break;
  }
  return [Math.min(1, Math.max(0, s)), Math.min(1, Math.max(0, t))];
}

/** The parameter of barycentric point w (float weights) of triangle t on its source face. */
export function faceParam(mesh: PreparedMesh, cage: Cage, t: number, w: readonly [number, number, number]): FaceParam {
  const face = mesh.triFace[t];
  const start = cage.faceOffsets[face];
  const n = cage.faceOffsets[face + 1] - start;
  // Corner indices (within the face) of the triangle's three corners; -1: the face's centre.
  const local = [0, 1, 2].map((i) => {
    const v = mesh.triVerts[3 * t + i];
    if (v >= mesh.cageVertexCount) return -1;
    for (let k = 0; k < n; k++) if (cage.faceIndices[start + k] === v) return k;
    throw new Error(`triangle ${t} is not on face ${face}`);
  });
  if (n === 4) {
    const uv = [
      [0, 0],
      [1, 0],
      [1, 1],
      [0, 1],
    ];
    let u = 0,
      v = 0;
    for (let i = 0; i < 3; i++) {
      u += w[i] * uv[local[i]][0];
      v += w[i] * uv[local[i]][1];
    }
    return { face, u, v };
  }
  // Point in the regular n-gon.
  const corner = (k: number) => (k < 0 ? [0, 0] : [Math.cos((2 * Math.PI * k) / n), Math.sin((2 * Math.PI * k) / n)]);
  const p: [number, number] = [0, 0];
  for (let i = 0; i < 3; i++) {
    const c = corner(local[i]);
    p[0] += w[i] * c[0];
    p[1] += w[i] * c[1];
  }
  // Sub-face k: the kite around corner k, i.e. the sector whose angle is nearest corner k.
  const angle = Math.atan2(p[1], p[0]);
  const k = ((Math.round((angle * n) / (2 * Math.PI)) % n) + n) % n;
  if (Math.hypot(p[0], p[1]) < 1e-14) return { face, k: 0, s: 1, t: 1 };
  const mid = (a: number, b: number) => {
    const ca = corner(a),
      cb = corner(b);
    return [(ca[0] + cb[0]) / 2, (ca[1] + cb[1]) / 2];
  };
  const [s, tt] = inverseBilinear(p, corner(k), mid(k, (k + 1) % n), [0, 0], mid((k + n - 1) % n, k));
  return { face, k, s, t: tt };
}
