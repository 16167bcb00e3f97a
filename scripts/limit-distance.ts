/**
 * How far the displayed surface is from the exact Catmull-Clark limit, in pixels (issue 13's
 * "smooth default"): every output vertex that faces the eye (its exact limit normal towards the
 * eye), against the exact CPU reference (src/subdiv, equal to OpenSubdiv) at the same cage
 * parameter, the distance divided by the size of a pixel at that vertex's distance from the eye
 * (|P − eye| · fovY / viewportHeight). The camera is the demo's first view (src/gpu/camera.ts
 * fitOrbit at the given aspect): what a user sees when the model loads.
 * A check tool (the CLI's --stats, tests): it reads the yardstick, which src/gpu never does.
 */
import { Surface } from '../src/subdiv/index.ts';
import { DEFAULT_OPTIONS, type Cage } from '../src/mesh/index.ts';
import type { PreparedMesh } from '../src/gpu/prepare.ts';
import type { MeshReadback } from '../src/gpu/readback.ts';
import { faceParam } from '../src/gpu/face-params.ts';
import { vertexWeights } from '../src/gpu/headless.ts';
import { boundsOf, eyePosition, fitOrbit, type Vec3 } from '../src/gpu/camera.ts';

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
