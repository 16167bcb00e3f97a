// Copy a linear picture (an -srgb texture: its loads decode to linear) to a canvas whose format
// has no -srgb view (WebGPU compatibility mode allows no format reinterpretation), encoding to
// sRGB here as the -srgb view would (src/gpu/render/srgb-blit.ts).

// source (group 0): src/gpu/contract/render.ts BLIT_GROUP, prepended.

@vertex
fn blitVertex(@builtin(vertex_index) i: u32) -> @builtin(position) vec4f {
  // One triangle over the whole target.
  let p = vec2f(f32((i << 1u) & 2u), f32(i & 2u));
  return vec4f(p * 2.0 - 1.0, 0.0, 1.0);
}

fn srgbFromLinear(c: vec3f) -> vec3f {
  let lo = c * 12.92;
  let hi = 1.055 * pow(c, vec3f(1.0 / 2.4)) - 0.055;
  return select(hi, lo, c <= vec3f(0.0031308));
}

@fragment
fn blitFragment(@builtin(position) at: vec4f) -> @location(0) vec4f {
  let c = textureLoad(source, vec2u(at.xy), 0);
  return vec4f(srgbFromLinear(clamp(c.rgb, vec3f(0.0), vec3f(1.0))), c.a);
}
