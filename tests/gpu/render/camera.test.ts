import { describe, expect, it } from 'vitest';
import { mat4 } from 'gl-matrix';
import {
  boundingSphere,
  boundsOf,
  cameraMatrices,
  clipPlanes,
  dolly,
  eyePosition,
  fitDistance,
  fitOrbit,
  lightViewProj,
  MAX_PITCH,
  orbit,
  perspectiveZO,
  transformBounds,
  transformPoint,
  upAxisMatrix,
  DEFAULT_LIGHT_DIR,
  type Bounds,
  type Vec3,
} from '../../../src/gpu/render/camera.ts';

const box: Bounds = { min: [-1, -2, -3], max: [3, 2, 1] };

function clip(m: ArrayLike<number>, p: Vec3): [number, number, number, number] {
  const [x, y, z] = p;
  const r = [0, 1, 2, 3].map((i) => m[i] * x + m[4 + i] * y + m[8 + i] * z + m[12 + i]);
  return r as [number, number, number, number];
}

describe('projection (WebGPU clip space, z in 0..1)', () => {
  it('maps the near plane to z = 0 and the far plane to z = 1', () => {
    const p = perspectiveZO(1, 1.5, 0.1, 100);
    for (const [depth, want] of [
      [0.1, 0],
      [100, 1],
    ] as const) {
      const c = clip(p, [0, 0, -depth]);
      expect(c[2] / c[3]).toBeCloseTo(want, 6);
    }
    // Half way in 1/z, not in z: the perspective depth curve.
    const mid = clip(p, [0, 0, -0.2]);
    expect(mid[2] / mid[3]).toBeGreaterThan(0.49);
  });

  it('is not the OpenGL (−1..1) projection', () => {
    const gl = mat4.perspective(mat4.create(), 1, 1.5, 0.1, 100);
    const c = clip(gl, [0, 0, -0.1]);
    expect(c[2] / c[3]).toBeCloseTo(-1, 6); // what WebGPU would clip away
  });
});

describe('orbit camera', () => {
  it('frames the bounding sphere: every corner of the box projects inside the viewport', () => {
    for (const aspect of [0.5, 1, 2.4]) {
      const cam = fitOrbit(box, aspect);
      const { viewProj } = cameraMatrices(cam, aspect);
      for (let i = 0; i < 8; i++) {
        const p: Vec3 = [i & 1 ? box.max[0] : box.min[0], i & 2 ? box.max[1] : box.min[1], i & 4 ? box.max[2] : box.min[2]];
        const [x, y, z, w] = clip(viewProj, p);
        expect(Math.abs(x / w)).toBeLessThan(1);
        expect(Math.abs(y / w)).toBeLessThan(1);
        expect(z / w).toBeGreaterThan(0);
        expect(z / w).toBeLessThan(1);
      }
    }
  });

  it('puts the eye at `distance` from the target and looks at the target (centre of the screen)', () => {
    const cam = { ...fitOrbit(box, 1), yaw: 0.7, pitch: -0.3 };
    const eye = eyePosition(cam);
    expect(Math.hypot(eye[0] - cam.target[0], eye[1] - cam.target[1], eye[2] - cam.target[2])).toBeCloseTo(cam.distance, 9);
    const m = cameraMatrices(cam, 1.3);
    expect(m.eye).toEqual(eye);
    const [x, y, , w] = clip(m.viewProj, cam.target);
    // gl-matrix works in float32.
    expect(x / w).toBeCloseTo(0, 6);
    expect(y / w).toBeCloseTo(0, 6);
  });

  it('a lens shift slides the picture sideways by the shift (clip units), perspective and depth unchanged', () => {
    const cam = { ...fitOrbit(box, 1.6), yaw: 0.4, pitch: 0.2 };
    const plain = cameraMatrices(cam, 1.6);
    const shifted = cameraMatrices(cam, 1.6, -0.27);
    for (const p of [cam.target, [3, 2, 1], [-1, -2, -3], [0.5, 1.7, -2.2]] as Vec3[]) {
      const [x, y, z, w] = clip(plain.viewProj, p);
      const [xs, ys, zs, ws] = clip(shifted.viewProj, p);
      expect(xs / ws).toBeCloseTo(x / w - 0.27, 5);
      expect(ys / ws).toBeCloseTo(y / w, 6);
      expect(zs / ws).toBeCloseTo(z / w, 6);
    }
  });

  it('yaw 0 and pitch 0 put the eye on +Z', () => {
    const cam = { ...fitOrbit(box, 1), yaw: 0, pitch: 0 };
    const eye = eyePosition(cam);
    expect(eye[0]).toBeCloseTo(cam.target[0], 12);
    expect(eye[1]).toBeCloseTo(cam.target[1], 12);
    expect(eye[2]).toBeGreaterThan(cam.target[2]);
  });

  it('clamps pitch short of the poles and wraps yaw', () => {
    const cam = fitOrbit(box, 1);
    expect(orbit(cam, 0, 10).pitch).toBe(MAX_PITCH);
    expect(orbit(cam, 0, -10).pitch).toBe(-MAX_PITCH);
    const turned = orbit(cam, 100, 0);
    expect(turned.yaw).toBeGreaterThanOrEqual(-Math.PI);
    expect(turned.yaw).toBeLessThan(Math.PI);
    expect(Math.cos(turned.yaw)).toBeCloseTo(Math.cos(cam.yaw + 100), 9);
  });

  it('dollies within limits relative to the model size', () => {
    const cam = fitOrbit(box, 1);
    const r = cam.subject.radius;
    expect(dolly(cam, 0.5).distance).toBeCloseTo(cam.distance * 0.5, 12);
    expect(dolly(cam, 1e-6).distance).toBeCloseTo(0.35 * r, 12);
    expect(dolly(cam, 1e6).distance).toBeCloseTo(40 * r, 12);
  });

  it('keeps near and far planes positive and ordered, holding the model at every zoom', () => {
    const cam = fitOrbit(box, 1);
    for (const f of [1e-6, 0.2, 1, 5, 1e6]) {
      const c = dolly(cam, f);
      const { near, far } = clipPlanes(c);
      expect(near).toBeGreaterThan(0);
      expect(far).toBeGreaterThan(near);
      expect(far).toBeGreaterThan(c.distance + c.subject.radius);
      if (c.distance > 2 * c.subject.radius) expect(near).toBeLessThan(c.distance - c.subject.radius);
    }
  });

  it('fitDistance grows with the radius and shrinks with a wider view', () => {
    expect(fitDistance(2, 1, 0.7)).toBeCloseTo(2 * fitDistance(1, 1, 0.7), 12);
    expect(fitDistance(1, 1, 1.2)).toBeLessThan(fitDistance(1, 1, 0.6));
    // A portrait view is limited by its narrow width.
    expect(fitDistance(1, 0.5, 0.7)).toBeGreaterThan(fitDistance(1, 1, 0.7));
  });
});

describe('bounds', () => {
  it('boundsOf finds min and max per axis', () => {
    expect(boundsOf([1, 2, 3, -1, 5, 0, 0, 0, 9])).toEqual({ min: [-1, 0, 0], max: [1, 5, 9] });
  });

  it('boundingSphere contains the box', () => {
    const s = boundingSphere(box);
    expect(s.center).toEqual([1, 0, -1]);
    expect(s.radius).toBeCloseTo(Math.hypot(4, 4, 4) / 2, 12);
  });

  it('a Z-up model turns so that +Z becomes +Y, without mirroring', () => {
    const m = upAxisMatrix('z');
    const up = transformPoint(m, [0, 0, 1]);
    expect(up[0]).toBeCloseTo(0, 12);
    expect(up[1]).toBeCloseTo(1, 12);
    expect(up[2]).toBeCloseTo(0, 12);
    expect(mat4.determinant(m)).toBeCloseTo(1, 12);
    expect(transformPoint(upAxisMatrix('y'), [1, 2, 3])).toEqual([1, 2, 3]);
    const b = transformBounds({ min: [-1, -2, 0], max: [1, 2, 5] }, m);
    expect(b.min.map((x) => +x.toFixed(9) + 0)).toEqual([-1, 0, -2]);
    expect(b.max.map((x) => +x.toFixed(9) + 0)).toEqual([1, 5, 2]);
  });
});

describe('light camera', () => {
  it('holds the whole bounding sphere inside its box, z in 0..1', () => {
    const s = boundingSphere(box);
    const m = lightViewProj(s, DEFAULT_LIGHT_DIR);
    const dirs: Vec3[] = [
      [1, 0, 0],
      [-1, 0, 0],
      [0, 1, 0],
      [0, -1, 0],
      [0, 0, 1],
      [0, 0, -1],
      [0.6, -0.6, 0.5],
    ];
    for (const d of dirs) {
      const n = Math.hypot(...d);
      const p: Vec3 = [
        s.center[0] + (d[0] / n) * s.radius * 0.999,
        s.center[1] + (d[1] / n) * s.radius * 0.999,
        s.center[2] + (d[2] / n) * s.radius * 0.999,
      ];
      const [x, y, z, w] = clip(m, p);
      expect(w).toBeCloseTo(1, 12); // orthographic
      expect(Math.abs(x)).toBeLessThanOrEqual(1);
      expect(Math.abs(y)).toBeLessThanOrEqual(1);
      expect(z).toBeGreaterThan(0);
      expect(z).toBeLessThan(1);
    }
  });

  it('is nearer to the light for points closer to it', () => {
    const s = boundingSphere(box);
    const m = lightViewProj(s, DEFAULT_LIGHT_DIR);
    const towards = (k: number): Vec3 => [
      s.center[0] + DEFAULT_LIGHT_DIR[0] * k,
      s.center[1] + DEFAULT_LIGHT_DIR[1] * k,
      s.center[2] + DEFAULT_LIGHT_DIR[2] * k,
    ];
    expect(clip(m, towards(s.radius * 0.5))[2]).toBeLessThan(clip(m, towards(-s.radius * 0.5))[2]);
  });

  it('reaches the ground below the model (where its shadow falls)', () => {
    const s = boundingSphere(box);
    const m = lightViewProj(s, DEFAULT_LIGHT_DIR);
    // The point on the ground (y = min) straight "behind" the sphere's lowest point along the light.
    const low: Vec3 = [s.center[0], s.center[1] - s.radius, s.center[2]];
    const z = clip(m, low)[2];
    expect(z).toBeLessThan(1);
  });
});
