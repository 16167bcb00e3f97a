// Shared by every render and wire shader (the renderer prepends it): the per-frame uniforms.

struct Frame {
  viewProj: mat4x4f,
  lightViewProj: mat4x4f,
  // Model to world: a rotation only (the model's up axis to +Y), so it also turns normals.
  model: mat4x4f,
  // xyz: the camera's position; w: the model's bounding radius.
  eye: vec4f,
  // xyz: unit vector towards the light; w: one shadow-map texel in uv units.
  toLight: vec4f,
  // xyz: the bounding sphere's centre; w: the ground's height.
  center: vec4f,
  // x, y: render target size in pixels; z: wireframe opacity; w: 1 for patch colours, else 0.
  viewport: vec4f,
}

@group(0) @binding(0) var<uniform> frame: Frame;

// Colours are written as sRGB, like a colour picker gives them; lighting happens in linear
// space and the render target is an -srgb view, which encodes on store.
fn linearFromSrgb(c: vec3f) -> vec3f {
  return pow(c, vec3f(2.2));
}

fn modelToWorld(p: vec3f) -> vec3f {
  return (frame.model * vec4f(p, 1.0)).xyz;
}

// Filmic tone curve (Narkowicz's fit of ACES): highlights roll off instead of clipping.
fn toneMap(c: vec3f) -> vec3f {
  let x = c * 0.8;
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), vec3f(0.0), vec3f(1.0));
}

// Lines (wireframe, cage) sit exactly on the surface they outline. Moving them a fixed
// fraction of the way to the eye wins the depth test at any distance; depthBias only
// applies to triangles.
fn pullTowardEye(p: vec3f, amount: f32) -> vec3f {
  return p + (frame.eye.xyz - p) * amount;
}
