/**
 * Where a surface's normals split at creases, for the crease-normal checks
 * (tests/gpu/cc/crease-normals.node.test.ts, tests/gpu/acc/crease-normals.node.test.ts): the output
 * vertices on a crease of sharpness ≥ sharpFrom (infinitely sharp for the limit surface, 1 for the
 * ACC schemes, which build those sharp), and the triangles with such a vertex whose normal is on
 * the wrong side.
 */
import type { MeshReadback } from '../../src/gpu/device/readback.ts';
import { decodeBary } from '../../src/gpu/contract/tess.ts';
import type { PreparedMesh } from '../../src/gpu/tess/prepare.ts';
import { type Cage, SHARPNESS_INFINITE } from '../../src/mesh/types.ts';

/** Which prepared vertices are where infinitely sharp creases meet (two or more such edges) or
 * carry an infinitely sharp corner tag (one such edge ending there is a dart: one normal), less
 * the cone points (see the header): a corner tag with an edge that is not infinitely sharp. */
export function creaseVertices(cage: Cage, mesh: PreparedMesh, sharpFrom = SHARPNESS_INFINITE): (v: number) => boolean {
  const incident = new Uint32Array(mesh.vertexCount);
  const edges = new Uint32Array(mesh.vertexCount);
  const sharp = sharpEdges(cage, sharpFrom);
  const nCage = cage.positions.length / 3;
  for (let e = 0; e < mesh.edgeCount; e++) {
    const ends = [mesh.edgeVerts[2 * e], mesh.edgeVerts[2 * e + 1]];
    if (ends[0] >= nCage || ends[1] >= nCage) continue; // an edge to an n-gon's centre is no cage edge
    for (const v of ends) {
      edges[v]++;
      if (sharp(ends[0], ends[1])) incident[v]++;
    }
  }
  const cornerTag = new Set(cage.corners.filter((c) => c.sharpness >= sharpFrom).map((c) => c.v));
  return (v) => (cornerTag.has(v) ? incident[v] === edges[v] : incident[v] >= 2);
}

function sharpEdges(cage: Cage, sharpFrom: number): (a: number, b: number) => boolean {
  const key = (a: number, b: number) => (a < b ? `${a},${b}` : `${b},${a}`);
  const sharp = new Set(cage.creases.filter((c) => c.sharpness >= sharpFrom).map((c) => key(c.v0, c.v1)));
  return (a, b) => sharp.has(key(a, b));
}

/** Which output vertices lie on an infinitely sharp crease, from each vertex's source triangle
 * and weights (so whatever the output's vertex order): a point with two nonzero weights on such
 * an edge, or a crease vertex (creaseVertices). */
export function creasePoints(cage: Cage, mesh: PreparedMesh, out: MeshReadback, sharpFrom = SHARPNESS_INFINITE): (v: number) => boolean {
  const sharp = sharpEdges(cage, sharpFrom);
  const atVertex = creaseVertices(cage, mesh, sharpFrom);
  return (v) => {
    const t = out.srcTri[v];
    if (t >= mesh.triangleCount) return false;
    const w = decodeBary(out.bary[v]);
    const on = [0, 1, 2].filter((i) => w[i] !== 0).map((i) => mesh.triVerts[3 * t + i]);
    if (on.length === 1) return atVertex(on[0]);
    return on.length === 2 && sharp(on[0], on[1]);
  };
}

/** Of the triangles with a vertex on an infinitely sharp crease: how many there are, and how
 * many have such a vertex whose normal is more than 45° from the triangle's geometric normal. */
export function wrongSide(o: MeshReadback, onCrease: (v: number) => boolean): { touching: number; wrong: number } {
  const P = o.positions,
    N = o.normals;
  let n = 0;
  let touching = 0;
  for (let t = 0; t < o.triangleCount; t++) {
    const [a, b, c] = [0, 1, 2].map((i) => o.indices[3 * t + i]);
    const e1 = [0, 1, 2].map((k) => P[3 * b + k] - P[3 * a + k]);
    const e2 = [0, 1, 2].map((k) => P[3 * c + k] - P[3 * a + k]);
    const g = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    const gl = Math.hypot(g[0], g[1], g[2]);
    if (gl === 0) continue;
    if (onCrease(a) || onCrease(b) || onCrease(c)) touching++;
    const off = (v: number) => onCrease(v) && N[3 * v] * g[0] + N[3 * v + 1] * g[1] + N[3 * v + 2] * g[2] < Math.SQRT1_2 * gl;
    if (off(a) || off(b) || off(c)) n++;
  }
  return { touching, wrong: n };
}
