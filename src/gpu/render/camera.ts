/**
 * Camera math for the demo: an orbit camera around a model, its WebGPU matrices, and the
 * orthographic light camera of the shadow map. Pure functions on plain data, no DOM, no GPU.
 *
 * WebGPU clip space has z in [0, 1], so every projection here is gl-matrix's ZO variant:
 * `mat4.perspective` / `mat4.ortho` are the OpenGL (−1..1) ones and would silently clip
 * everything nearer than about twice the near plane.
 */
import { mat4, vec3 } from 'gl-matrix';
import { GROUND_EXTENT } from '../contract/render.ts';

export type Vec3 = [number, number, number];

export interface Bounds {
  min: Vec3;
  max: Vec3;
}

export interface Sphere {
  center: Vec3;
  radius: number;
}

/** An orbit (turntable) camera: +Y is up, yaw turns around it, pitch tilts towards it. */
export interface OrbitCamera {
  target: Vec3;
  distance: number;
  /** Radians around +Y; 0 looks down −Z (the eye sits on +Z). */
  yaw: number;
  /** Radians above the horizon, kept inside ±MAX_PITCH so the view never flips. */
  pitch: number;
  /** Vertical field of view, radians. */
  fovY: number;
  /** The model's bounding sphere: it sets the zoom range and the near and far planes. */
  subject: Sphere;
}

export interface CameraMatrices {
  view: mat4;
  proj: mat4;
  viewProj: mat4;
  eye: Vec3;
  near: number;
  far: number;
}

export const MAX_PITCH = Math.PI / 2 - 0.01;
export const DEFAULT_FOV_Y = (40 * Math.PI) / 180;
/** How far the ground plane reaches from the model's centre, in bounding radii (declared in
 * contract/render.ts: the ground shader reads the same number). */
export { GROUND_EXTENT };

/** Axis-aligned bounds of xyz triples. Empty input gives the unit cube around the origin. */
export function boundsOf(positions: ArrayLike<number>): Bounds {
  if (positions.length < 3) return { min: [-1, -1, -1], max: [1, 1, 1] };
  const min: Vec3 = [Infinity, Infinity, Infinity];
  const max: Vec3 = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i + 2 < positions.length; i += 3) {
    for (let k = 0; k < 3; k++) {
      const x = positions[i + k];
      if (x < min[k]) min[k] = x;
      if (x > max[k]) max[k] = x;
    }
  }
  return { min, max };
}

/** The sphere around the box (not the tightest one, but stable and cheap). */
export function boundingSphere(b: Bounds): Sphere {
  const center: Vec3 = [(b.min[0] + b.max[0]) / 2, (b.min[1] + b.max[1]) / 2, (b.min[2] + b.max[2]) / 2];
  const radius = Math.hypot(b.max[0] - b.min[0], b.max[1] - b.min[1], b.max[2] - b.min[2]) / 2;
  return { center, radius: radius > 0 ? radius : 1 };
}

/** A camera that frames the sphere from the front, a little above, whatever the aspect. */
export function fitOrbit(bounds: Bounds, aspect: number, fovY = DEFAULT_FOV_Y): OrbitCamera {
  const subject = boundingSphere(bounds);
  return {
    target: [...subject.center],
    distance: fitDistance(subject.radius, aspect, fovY),
    yaw: 0.55,
    pitch: 0.36,
    fovY,
    subject,
  };
}

/** Distance at which a sphere of this radius just fits both the vertical and horizontal field of view. */
export function fitDistance(radius: number, aspect: number, fovY: number): number {
  const fovX = 2 * Math.atan(Math.tan(fovY / 2) * Math.max(aspect, 1e-3));
  const half = Math.min(fovY, fovX) / 2;
  // A margin around the sphere leaves room for the page's panels.
  return (radius / Math.sin(half)) * 1.2;
}

export function eyePosition(cam: OrbitCamera): Vec3 {
  const cp = Math.cos(cam.pitch);
  return [
    cam.target[0] + cam.distance * cp * Math.sin(cam.yaw),
    cam.target[1] + cam.distance * Math.sin(cam.pitch),
    cam.target[2] + cam.distance * cp * Math.cos(cam.yaw),
  ];
}

/** Turn the camera: angles in radians, pitch clamped so the up vector never flips. */
export function orbit(cam: OrbitCamera, dYaw: number, dPitch: number): OrbitCamera {
  const pitch = Math.min(MAX_PITCH, Math.max(-MAX_PITCH, cam.pitch + dPitch));
  return { ...cam, yaw: wrapAngle(cam.yaw + dYaw), pitch };
}

/** Move towards (factor < 1) or away from (factor > 1) the target, within sensible limits. */
export function dolly(cam: OrbitCamera, factor: number): OrbitCamera {
  const r = cam.subject.radius;
  // Never inside the model's sphere's inner half, never so far that it is a speck.
  const distance = Math.min(r * 40, Math.max(r * 0.35, cam.distance * factor));
  return { ...cam, distance };
}

function wrapAngle(a: number): number {
  const t = 2 * Math.PI;
  return a - t * Math.floor((a + Math.PI) / t);
}

/**
 * Near and far planes that hold the model and the ground: far reaches past the ground's edge,
 * near is as far out as possible (depth precision) but never behind a close-up's front face.
 */
export function clipPlanes(cam: OrbitCamera): { near: number; far: number } {
  const r = cam.subject.radius;
  const far = cam.distance + r * (GROUND_EXTENT + 1);
  const near = Math.max(cam.distance - r * (GROUND_EXTENT + 1), cam.distance * 0.02, r * 0.001);
  return { near: Math.min(near, far * 0.5), far };
}

/** WebGPU (z in 0..1) perspective projection. */
export function perspectiveZO(fovY: number, aspect: number, near: number, far: number): mat4 {
  return mat4.perspectiveZO(mat4.create(), fovY, aspect, near, far);
}

/**
 * The camera's matrices. `shiftX` is a lens shift in clip units (2 = the image's width): the
 * picture slides sideways with its perspective unchanged, as a view camera's shifted lens, so a
 * page can frame its subject in the part of the canvas its panels leave free.
 */
export function cameraMatrices(cam: OrbitCamera, aspect: number, shiftX = 0): CameraMatrices {
  const eye = eyePosition(cam);
  const view = mat4.lookAt(mat4.create(), eye, cam.target, [0, 1, 0]);
  const { near, far } = clipPlanes(cam);
  const proj = perspectiveZO(cam.fovY, aspect, near, far);
  // x_clip += shiftX · w_clip: row 0 gains shiftX times row 3 (column-major).
  for (let c = 0; c < 4; c++) proj[4 * c] += shiftX * proj[4 * c + 3];
  const viewProj = mat4.multiply(mat4.create(), proj, view);
  return { view, proj, viewProj, eye, near, far };
}

/** Unit vector towards the light: a sun high on the left of the default view, so the shadow falls into view. */
export const DEFAULT_LIGHT_DIR: Vec3 = normalize([-0.65, 1.0, 0.5]);

export function normalize(v: Vec3): Vec3 {
  const n = Math.hypot(v[0], v[1], v[2]) || 1;
  return [v[0] / n, v[1] / n, v[2] / n];
}

/**
 * The shadow map's camera: orthographic, looking along −towardLight, its box fitted around the
 * model's bounding sphere so the whole model always casts into the map, and deep enough to reach
 * the ground under it (shadows fall on the ground beyond the sphere).
 */
export function lightViewProj(subject: Sphere, towardLight: Vec3): mat4 {
  const r = subject.radius;
  const c = subject.center;
  const d = normalize(towardLight);
  const eye: Vec3 = [c[0] + d[0] * 2 * r, c[1] + d[1] * 2 * r, c[2] + d[2] * 2 * r];
  // Any up vector not parallel to the light direction.
  const up: Vec3 = Math.abs(d[1]) > 0.99 ? [0, 0, 1] : [0, 1, 0];
  const view = mat4.lookAt(mat4.create(), eye, c, up);
  const depth = 2 * r + r * (GROUND_EXTENT + 2);
  const proj = mat4.orthoZO(mat4.create(), -r, r, -r, r, r * 0.5, depth);
  return mat4.multiply(mat4.create(), proj, view);
}

export type UpAxis = 'y' | 'z';

/**
 * Model to world for a model authored with this axis up: the world is +Y up, so a Z-up model
 * (the project's models, CAD, OpenSubdiv's shapes) turns −90° about X: (x, y, z) → (x, z, −y).
 * A rotation: it turns normals too, and keeps the winding.
 */
export function upAxisMatrix(up: UpAxis): mat4 {
  const m = mat4.create();
  if (up === 'z') mat4.fromXRotation(m, -Math.PI / 2);
  return m;
}

/** The box around a transformed box (its eight corners). */
export function transformBounds(b: Bounds, m: ArrayLike<number>): Bounds {
  const corners: number[] = [];
  for (let i = 0; i < 8; i++) {
    const p = transformPoint(m, [i & 1 ? b.max[0] : b.min[0], i & 2 ? b.max[1] : b.min[1], i & 4 ? b.max[2] : b.min[2]]);
    corners.push(...p);
  }
  return boundsOf(corners);
}

/** Multiply a point by a column-major 4×4 matrix and divide by w (for tests and picking). */
export function transformPoint(m: ArrayLike<number>, p: Vec3): Vec3 {
  const out = vec3.transformMat4(vec3.create(), p, m as mat4);
  return [out[0], out[1], out[2]];
}
