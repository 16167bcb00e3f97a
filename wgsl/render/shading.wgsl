// Lighting shared by the lit mesh and the ground (the renderer prepends wgsl/render/common.wgsl).

// shadowMap and shadowSampler (group 1): src/gpu/contract/render.ts SHADING_GROUP, prepended.

const SUN = vec3f(1.0, 0.94, 0.86) * 2.2;

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
