// Cage overlay: the control polygon's edges, crease edges in their own colour, drawn twice:
// faintly where the surface hides them, fully where they are in front (prepended:
// wgsl/render/common.wgsl).

override OPACITY: f32 = 1.0;

struct VertexOut {
  @builtin(position) clip: vec4f,
  @location(0) colour: vec4f,
}

@vertex
fn cageVertex(@location(0) position: vec3f, @location(1) colour: vec4f) -> VertexOut {
  var out: VertexOut;
  out.clip = scene.viewProj * vec4f(pullTowardEye(modelToWorld(position), 2e-3), 1.0);
  out.colour = colour;
  return out;
}

@fragment
fn cageFragment(in: VertexOut) -> @location(0) vec4f {
  return vec4f(linearFromSrgb(in.colour.rgb), in.colour.a * OPACITY);
}
