// Lighting shared by the lit mesh and the ground (the renderer prepends wgsl/render/common.wgsl).

// shadowMap and shadowSampler (group 1): src/gpu/contract/render.ts SHADING_GROUP, prepended.

// The studio rig: a warm key (the one light that casts the shadow map, towards scene.toLight), a
// cool fill from the opposite side and lower, unshadowed, so the key's shadow side keeps its
// form; a back light above and behind the model as the camera sees it, which draws its outline
// against the dark backdrop; and the hemisphere ambient below. Metal reflects the same rig as an
// environment (studioRadiance): its two lights as soft boxes over a graded sky.
const KEY = vec3f(1.0, 0.94, 0.86) * 2.0;
const FILL = vec3f(0.60, 0.72, 1.0) * 0.42;
const BACK = vec3f(1.0, 0.96, 0.90) * 0.85;

fn fillDirection() -> vec3f {
  return normalize(vec3f(-scene.toLight.x, 0.35, -scene.toLight.z));
}

// Behind the model from the camera (the bounding sphere's centre seen from the eye), raised.
fn backDirection() -> vec3f {
  let away = scene.center.xyz - scene.eye.xyz;
  let flat = normalize(vec3f(away.x, 0.0, away.z) + vec3f(1e-6, 0.0, 0.0));
  return normalize(flat + vec3f(0.0, 1.1, 0.0));
}

// What a mirror sees in direction d: the sky graded from the floor's dark to a pale top, and the
// key and fill as soft boxes (the key's share is returned apart, so the shadow can dim it).
struct Studio {
  sky: vec3f,
  key: vec3f,
}

fn studioRadiance(d: vec3f) -> Studio {
  // A studio's cyclorama: a grey floor, a bright band at the horizon (what the sides of a model
  // seen from above reflect), a paler top.
  let floor = linearFromSrgb(vec3f(0.56, 0.56, 0.58));
  let band = linearFromSrgb(vec3f(0.95, 0.96, 0.98));
  let top = linearFromSrgb(vec3f(0.80, 0.84, 0.92));
  let sky = mix(mix(floor, band, smoothstep(-0.6, 0.0, d.y)), top, smoothstep(0.1, 0.9, d.y))
    + FILL * 2.2 * pow(max(dot(d, fillDirection()), 0.0), 10.0)
    + BACK * 0.8 * pow(max(dot(d, backDirection()), 0.0), 16.0);
  let key = KEY * 1.4 * pow(max(dot(d, scene.toLight.xyz), 0.0), 28.0);
  return Studio(sky, key);
}

// Hemisphere ambient: cool sky above, warm bounce from the ground below.
fn ambient(n: vec3f) -> vec3f {
  let sky = linearFromSrgb(vec3f(0.64, 0.72, 0.84));
  let bounce = linearFromSrgb(vec3f(0.36, 0.32, 0.30));
  return mix(bounce, sky, 0.5 + 0.5 * n.y) * 0.7;
}

// 0 in shadow, 1 lit. 4×4 taps of the hardware's bilinear comparison: a soft, stable edge.
fn shadowFactor(world: vec3f, n: vec3f) -> f32 {
  let texel = scene.toLight.w;
  // Normal offset: look the point up a little off the surface, further where the light grazes
  // it (that is where one shadow texel spans the most surface), to keep acne away.
  let worldTexel = 2.0 * scene.eye.w * texel;
  let grazing = 1.0 - clamp(dot(n, scene.toLight.xyz), 0.0, 1.0);
  let p = scene.lightViewProj * vec4f(world + n * worldTexel * (0.6 + 1.6 * grazing), 1.0);
  let uv = p.xy * vec2f(0.5, -0.5) + 0.5;
  var sum = 0.0;
  for (var y = 0; y < 4; y++) {
    for (var x = 0; x < 4; x++) {
      let offset = (vec2f(f32(x), f32(y)) - 1.5) * texel;
      sum += textureSampleCompareLevel(shadowMap, shadowSampler, uv + offset, p.z);
    }
  }
  // Outside the light's box nothing casts a shadow.
  let inside = all(uv > vec2f(0.0)) && all(uv < vec2f(1.0)) && p.z < 1.0;
  return select(1.0, sum / 16.0, inside);
}
