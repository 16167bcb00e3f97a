// Backdrop: a vertical gradient with a soft vignette, one full-screen triangle, drawn first
// (the renderer prepends wgsl/render/common.wgsl).

struct VertexOut {
  @builtin(position) clip: vec4f,
  @location(0) uv: vec2f,
}

@vertex
fn backdropVertex(@builtin(vertex_index) i: u32) -> VertexOut {
  let uv = vec2f(f32((i << 1u) & 2u), f32(i & 2u));
  var out: VertexOut;
  out.clip = vec4f(uv * 2.0 - 1.0, 1.0, 1.0);
  out.uv = vec2f(uv.x, 1.0 - uv.y);
  return out;
}

@fragment
fn backdropFragment(in: VertexOut) -> @location(0) vec4f {
  let top = linearFromSrgb(vec3f(0.21, 0.23, 0.28));
  let bottom = linearFromSrgb(vec3f(0.10, 0.11, 0.13));
  var colour = mix(top, bottom, smoothstep(0.0, 1.0, in.uv.y));
  let aspect = scene.viewport.x / max(scene.viewport.y, 1.0);
  let d = length((in.uv - 0.5) * vec2f(aspect, 1.0));
  colour *= 1.0 - 0.3 * smoothstep(0.45, 1.2, d);
  return vec4f(colour, 1.0);
}
