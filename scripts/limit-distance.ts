/**
 * How far the displayed surface is from the exact Catmull-Clark limit, in pixels (issue 13's
 * "smooth default"): every output vertex that faces the eye (its exact limit normal towards the
 * eye), against the exact CPU reference (src/subdiv, equal to OpenSubdiv) at the same cage
 * parameter, the distance divided by the size of a pixel at that vertex's distance from the eye
 * (|P − eye| · fovY / viewportHeight). The camera is the demo's first view (src/gpu/render/camera.ts
 * fitOrbit at the given aspect): what a user sees when the model loads.
 * A check tool (the CLI's --stats, tests): it reads the yardstick, which src/gpu never does.
 */
import { Surface } from '../src/subdiv/index.ts';
import { DEFAULT_OPTIONS, type Cage } from '../src/mesh/index.ts';
import type { PreparedMesh } from '../src/gpu/tess/prepare.ts';
import type { MeshReadback } from '../src/gpu/device/readback.ts';
import { faceParam } from '../src/gpu/tess/face-params.ts';
import { vertexWeights } from '../src/gpu/tess/headless.ts';
import { boundsOf, eyePosition, fitOrbit, type Vec3 } from '../src/gpu/render/camera.ts';

export interface DemoView {
  eye: Vec3;
  target: Vec3;
  fovY: number;
  viewportHeight: number;
}

/** The demo's first view of a model on a canvas of this size (its default orbit, fitted). */
export function demoView(mesh: PreparedMesh, width = 1280, height = 720): DemoView {
  const cam = fitOrbit(boundsOf(mesh.positions), width / height);
  return { eye: eyePosition(cam), target: [...cam.target] as Vec3, fovY: cam.fovY, viewportHeight: height };
}

export interface LimitDistance {
  /** Vertices held (facing the eye). */
  count: number;
  maxPx: number;
  p99Px: number;
  worst: string;
}

export function limitDistancePx(
  cage: Cage,
  mesh: PreparedMesh,
  out: MeshReadback,
  view: Pick<DemoView, 'eye' | 'fovY' | 'viewportHeight'>,
): LimitDistance {
  const S = new Surface(cage, undefined, { ...DEFAULT_OPTIONS, ...cage.fileOptions });
  const pixelAngle = view.fovY / view.viewportHeight;
  const used = new Uint8Array(out.vertexCount);
  for (let i = 0; i < 3 * out.triangleCount; i++) used[out.indices[i]] = 1;
  const px: number[] = [];
  let worst = '',
    worstPx = -1;
  for (let v = 0; v < out.vertexCount; v++) {
    if (!used[v]) continue;
    const fp = faceParam(mesh, cage, out.srcTri[v], vertexWeights(out, v));
    const r = 'k' in fp ? S.evaluateSubFace(fp.face, fp.k, fp.s, fp.t) : S.evaluate(fp.face, fp.u, fp.v);
    const P = r.P,
      N = r.N;
    const toEye = [view.eye[0] - P[0], view.eye[1] - P[1], view.eye[2] - P[2]];
    const dist = Math.hypot(toEye[0], toEye[1], toEye[2]);
    if (!(N[0] * toEye[0] + N[1] * toEye[1] + N[2] * toEye[2] > 0)) continue; // faces away (or no normal)
    const d = Math.hypot(out.positions[3 * v] - P[0], out.positions[3 * v + 1] - P[1], out.positions[3 * v + 2] - P[2]);
    const p = d / (dist * pixelAngle);
    px.push(p);
    if (p > worstPx) {
      worstPx = p;
      worst = `vertex ${v} face ${fp.face}`;
    }
  }
  px.sort((a, b) => a - b);
  return { count: px.length, maxPx: px[px.length - 1] ?? 0, p99Px: px[Math.floor(0.99 * (px.length - 1))] ?? 0, worst };
}

/**
 * The same measure between the vertices: what is drawn there is the flat triangle, so the point
 * shown at an output edge's midpoint is the mean of its two vertices, and at a triangle's
 * centroid the mean of three. Each sample is compared with the exact limit at the mean of the
 * vertices' cage parameters, taken on one cage triangle: the vertices' barycentric weights are
 * rewritten over that triangle's corners (a vertex is stored on one of the cage triangles it
 * lies on, perhaps not the one the output triangle came from; its weights name only corners that
 * all of them share). Output triangles whose vertices cannot all be written on one cage triangle
 * are counted as skipped (none are expected: the tessellator emits each triangle inside one). Held: samples whose limit
 * normal faces the eye. The distance is taken along the limit normal there (the first-order
 * distance to the surface). This is the displayed surface's distance from the limit: the blend's
 * offset at the vertices plus the chord's sag between them (issue 13 asks for 1 px at LOD 1).
 */
export function displayedDistancePx(
  cage: Cage,
  mesh: PreparedMesh,
  out: MeshReadback,
  view: Pick<DemoView, 'eye' | 'fovY' | 'viewportHeight'>,
  /** Each held sample: its distance (px), cage triangle, weights, and cosine to the eye. */
  onSample?: (px: number, t: number, w: readonly number[], cos: number) => void,
): LimitDistance & { skipped: number } {
  const S = new Surface(cage, undefined, { ...DEFAULT_OPTIONS, ...cage.fileOptions });
  const pixelAngle = view.fovY / view.viewportHeight;
  /** Vertex v's weights over the corners of cage triangle t, or undefined if it is not on t. */
  const weightsOn = (v: number, t: number): [number, number, number] | undefined => {
    const s = out.srcTri[v];
    const w = vertexWeights(out, v);
    if (s === t) return w;
    const r: [number, number, number] = [0, 0, 0];
    for (let i = 0; i < 3; i++) {
      if (w[i] === 0) continue;
      const id = mesh.triVerts[3 * s + i];
      let j = 0;
      while (j < 3 && mesh.triVerts[3 * t + j] !== id) j++;
      if (j === 3) return undefined;
      r[j] = w[i];
    }
    return r;
  };
  const trianglesAt = new Map<number, number[]>();
  for (let t = 0; t < mesh.triangleCount; t++) {
    for (let i = 0; i < 3; i++) {
      const id = mesh.triVerts[3 * t + i];
      const list = trianglesAt.get(id);
      if (list) list.push(t);
      else trianglesAt.set(id, [t]);
    }
  }
  const px: number[] = [];
  let worst = '',
    worstPx = -1,
    skipped = 0;
  const sample = (t: number, verts: number[], ws: [number, number, number][], what: string) => {
    const w: [number, number, number] = [0, 0, 0];
    const shown = [0, 0, 0];
    for (let k = 0; k < verts.length; k++) {
      for (let i = 0; i < 3; i++) {
        w[i] += ws[k][i] / verts.length;
        shown[i] += out.positions[3 * verts[k] + i] / verts.length;
      }
    }
    const fp = faceParam(mesh, cage, t, w);
    const r = 'k' in fp ? S.evaluateSubFace(fp.face, fp.k, fp.s, fp.t) : S.evaluate(fp.face, fp.u, fp.v);
    const P = r.P,
      N = r.N;
    const toEye = [view.eye[0] - P[0], view.eye[1] - P[1], view.eye[2] - P[2]];
    if (!(N[0] * toEye[0] + N[1] * toEye[1] + N[2] * toEye[2] > 0)) return;
    // Along the limit normal: the sample's offset within the surface (the chord's midpoint lies at
    // another parameter than its vertices' mean) moves no pixel of the shape.
    const nl = Math.hypot(N[0], N[1], N[2]);
    const dist = Math.hypot(toEye[0], toEye[1], toEye[2]);
    const off = (shown[0] - P[0]) * N[0] + (shown[1] - P[1]) * N[1] + (shown[2] - P[2]) * N[2];
    const p = Math.abs(off) / nl / (dist * pixelAngle);
    const cos = (N[0] * toEye[0] + N[1] * toEye[1] + N[2] * toEye[2]) / (nl * dist);
    px.push(p);
    onSample?.(p, t, w, cos);
    if (p > worstPx) {
      worstPx = p;
      worst = `${what} face ${fp.face} (cage triangle ${t}, weights ${w.map((x) => x.toFixed(3)).join(',')}, limit normal·view ${cos.toFixed(3)})`;
    }
  };
  for (let tri = 0; tri < out.triangleCount; tri++) {
    const v = [0, 1, 2].map((i) => out.indices[3 * tri + i]);
    // The cage triangle it lies in: one round a corner that its first vertex's weights name.
    let t = -1;
    let ws: [number, number, number][] = [];
    const s0 = out.srcTri[v[0]];
    const w0 = vertexWeights(out, v[0]);
    for (let i = 0; i < 3 && t < 0; i++) {
      if (w0[i] === 0) continue;
      for (const c of trianglesAt.get(mesh.triVerts[3 * s0 + i]) ?? []) {
        const cand = v.map((u) => weightsOn(u, c));
        if (cand.every((x) => x !== undefined)) {
          t = c;
          ws = cand as [number, number, number][];
          break;
        }
      }
    }
    if (t < 0) {
      skipped++;
      continue;
    }
    for (let i = 0; i < 3; i++) sample(t, [v[i], v[(i + 1) % 3]], [ws[i], ws[(i + 1) % 3]], `midpoint of ${v[i]}–${v[(i + 1) % 3]}`);
    sample(t, v, ws, `centroid of triangle ${tri}`);
  }
  px.sort((a, b) => a - b);
  return { count: px.length, maxPx: px[px.length - 1] ?? 0, p99Px: px[Math.floor(0.99 * (px.length - 1))] ?? 0, worst, skipped };
}
