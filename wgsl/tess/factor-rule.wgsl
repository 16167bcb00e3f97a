// The adaptive factor rule's curvature measure for one edge, shared by the compute tessellator
// (wgsl/tess/factors.wgsl adaptiveFactor) and the instanced tessellator's factor-rule mode
// (wgsl/instanced/levels.wgsl edgeFactorRule). Its double-precision twin, and the derivation, is
// src/gpu/tess/factors.ts edgeFactor. Both preludes define PHONG_ALPHA.

struct EdgeBend {
  // Phong midpoint minus linear midpoint: symmetric in the two ends.
  off: vec3<f32>,
  // The Phong midpoint: the centre of the edge's bounding sphere.
  mid: vec3<f32>,
  // Both ends face away from the eye (factor 1), or both face it.
  away: bool,
  facing: bool,
}

fn edgeBend(p0: vec3<f32>, n0: vec3<f32>, p1: vec3<f32>, n1: vec3<f32>, eye: vec3<f32>) -> EdgeBend {
  let d = p1 - p0;
  let off = (PHONG_ALPHA / 4.0) * (dot(d, n1) * n1 - dot(d, n0) * n0);
  let toEye0 = eye - p0;
  let toEye1 = eye - p1;
  let c0 = dot(n0, toEye0);
  let c1 = dot(n1, toEye1);
  let l0 = 0.1 * length(toEye0);
  let l1 = 0.1 * length(toEye1);
  let away = (c0 < -l0) && (c1 < -l1);
  let facing = (c0 > l0) && (c1 > l1);
  return EdgeBend(off, 0.5 * (p0 + p1) + off, away, facing);
}

// Equal segments for a chord error of 1/lodScale pixels: k = sqrt(lodScale·err / (dist·pixelAngle))
// (Hable's line at factor k has longer ones inside an octave: src/gpu/tess/factors.ts says how much).
// On an edge facing the eye the offset's part across the line of sight (which moves silhouettes
// and occlusion contours on screen) counts twice.
fn bendFactor(b: EdgeBend, eye: vec3<f32>, lodScale: f32, pixelAngle: f32) -> f32 {
  let dist = max(length(b.mid - eye), 1e-6);
  let ray = (b.mid - eye) / dist;
  let err = length(b.off);
  let across = length(b.off - dot(b.off, ray) * ray);
  let seen = select(err, max(err, 2.0 * across), b.facing);
  return sqrt(lodScale * seen / (dist * pixelAngle));
}
