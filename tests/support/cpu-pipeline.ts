/**
 * The whole adaptive pipeline on the CPU, from the pieces the GPU passes are held to: the
 * factor rule (src/gpu/surface/phong.ts phongEdgeFactors: src/gpu/tess/factors.ts edgeFactor with its two
 * triangles' bulge term, one factor per mesh edge in its canonical lower→higher direction), the
 * pattern (src/pattern/clamped.ts clampedTriangle with the reverse flags prepare.ts uses) and the Phong surface (src/gpu/surface/phong.ts phongPoint). No welding: each
 * cage triangle's pattern is evaluated on its own, which gives the same positions as the welded
 * GPU mesh (shared edge points are bit-identical barycentrics) and keeps track of where every
 * output triangle came from.
 */
import { mat4 } from 'gl-matrix';
import type { FactorRule, Vec3 } from '../../src/gpu/tess/factors.ts';
import { phongEdgeFactors, phongPoint } from '../../src/gpu/surface/phong.ts';
import type { PreparedMesh } from '../../src/gpu/tess/prepare.ts';
import { clampedTriangle, type Reverse } from '../../src/pattern/clamped.ts';
import { ONE } from '../../src/pattern/fixed.ts';

/** A camera looking at `target` from `eye` (WebGPU clip space), as the factor rule wants it. */
export function cameraRule(
  mode: 'fixed' | 'adaptive',
  eye: Vec3,
  target: Vec3,
  size: number,
  opts: { fixedFactor?: number; lodScale?: number; fovY?: number; viewportHeight?: number; maxFactor?: number } = {},
): FactorRule {
  const fovY = opts.fovY ?? Math.PI / 4;
  const dist = Math.hypot(eye[0] - target[0], eye[1] - target[1], eye[2] - target[2]);
  const view = mat4.lookAt(mat4.create(), eye as [number, number, number], target as [number, number, number], [0, 1, 0]);
  const proj = mat4.perspectiveZO(mat4.create(), fovY, 16 / 9, Math.max(1e-4, dist * 1e-3), dist + 4 * size);
  return {
    mode,
    fixedFactor: opts.fixedFactor ?? 1,
    lodScale: opts.lodScale ?? 1,
    viewProj: mat4.multiply(mat4.create(), proj, view),
    eye,
    pixelAngle: fovY / (opts.viewportHeight ?? 1080),
    maxFactor: opts.maxFactor ?? 64,
  };
}

/** How many views the fold tests take (six until 2026-11-27: over six, the other models' zero
 * folds were the luck of the views). */
export const FOLD_VIEWS = 24;

/** The fold tests' views of a model (tests/gpu/tess/no-folds.test.ts, tests/gpu/tess/folds.node.test.ts): FOLD_VIEWS
 * cameras round its centre from a seeded generator (an LCG, so every run sees the same ones), at
 * 0.6 to 2 times its size, LOD scales 0.5, 1 and 2 in turn. */
export function foldCameras(mesh: PreparedMesh): { eye: Vec3; target: Vec3; lodScale: number }[] {
  const target = [0, 1, 2].map((i) => (mesh.bboxMin[i] + mesh.bboxMax[i]) / 2) as unknown as Vec3;
  let s = 12345;
  const rnd = () => (s = (s * 1103515245 + 12345) % 2147483648) / 2147483648;
  return Array.from({ length: FOLD_VIEWS }, (_, cam) => {
    const yaw = rnd() * 2 * Math.PI,
      pitch = (rnd() - 0.5) * 2.4,
      dist = mesh.size * (0.6 + 1.4 * rnd());
    const eye: Vec3 = [
      target[0] + dist * Math.cos(pitch) * Math.sin(yaw),
      target[1] + dist * Math.sin(pitch),
      target[2] + dist * Math.cos(pitch) * Math.cos(yaw),
    ];
    return { eye, target, lodScale: [0.5, 1, 2][cam % 3] };
  });
}

export interface CpuTriangle {
  /** The three corners' positions and unit normals (the surface's normals at them). */
  p: [number[], number[], number[]];
  n: [number[], number[], number[]];
  /** Source cage triangle, its three edge factors (16.16-exact numbers) and reverse flags,
   * and the triangle's index in that pattern. */
  cageTri: number;
  factors: [number, number, number];
  reverse: Reverse;
  local: number;
}

/** Every output triangle of the CPU pipeline, in the pattern's (positive) winding. */
export function cpuTessellate(mesh: PreparedMesh, rule: FactorRule, trueNormals = false): CpuTriangle[] {
  // The GPU stores the factor as 16.16; so does this, so both see the same line state.
  const edgeF = phongEdgeFactors(mesh, rule).map((f) => Math.round(f * ONE) / ONE);
  const out: CpuTriangle[] = [];
  for (let t = 0; t < mesh.triangleCount; t++) {
    const tv = [0, 1, 2].map((i) => mesh.triVerts[3 * t + i]);
    const factors = [0, 1, 2].map((i) => edgeF[mesh.triEdges[3 * t + i]]) as [number, number, number];
    const reverse = [0, 1, 2].map((i) => tv[i] > tv[(i + 1) % 3]) as unknown as Reverse;
    const pat = clampedTriangle(factors, reverse);
    const pts: { pos: number[]; normal: number[] }[] = [];
    for (let v = 0; v < pat.vertexCount; v++) {
      const w: [number, number, number] = [pat.bary[3 * v] / ONE, pat.bary[3 * v + 1] / ONE, pat.bary[3 * v + 2] / ONE];
      const pt = phongPoint(mesh, t, w);
      pts.push(trueNormals ? { pos: pt.pos, normal: phongSurfaceNormal(mesh, t, w) } : pt);
    }
    for (let k = 0; k < pat.triangleCount; k++) {
      const c = [0, 1, 2].map((i) => pts[pat.triangles[3 * k + i]]);
      out.push({ p: [c[0].pos, c[1].pos, c[2].pos], n: [c[0].normal, c[1].normal, c[2].normal], cageTri: t, factors, reverse, local: k });
    }
  }
  return out;
}

/** The triangle's geometric normal (not normalised; zero for a degenerate triangle). */
export function geometricNormal(t: CpuTriangle): number[] {
  const [a, b, c] = t.p;
  const e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  return [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
}

/** The Phong surface's own unit normal at w: the cross product of its two barycentric
 * derivatives (central differences; the surface is quadratic in w, so they are exact up to
 * rounding), in the cage triangle's winding. */
export function phongSurfaceNormal(mesh: PreparedMesh, t: number, w: readonly [number, number, number]): number[] {
  const h = 1e-4;
  const at = (d1: number, d2: number) => phongPoint(mesh, t, [w[0] - d1 - d2, w[1] + d1, w[2] + d2]).pos;
  const a = at(h, 0),
    b = at(-h, 0),
    c = at(0, h),
    d = at(0, -h);
  const t1 = [0, 1, 2].map((i) => a[i] - b[i]);
  const t2 = [0, 1, 2].map((i) => c[i] - d[i]);
  const n = [t1[1] * t2[2] - t1[2] * t2[1], t1[2] * t2[0] - t1[0] * t2[2], t1[0] * t2[1] - t1[1] * t2[0]];
  const l = Math.hypot(n[0], n[1], n[2]);
  return l > 0 ? n.map((x) => x / l) : n;
}
