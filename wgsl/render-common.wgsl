// Shared by every render and wire shader (the renderer prepends it). Before it comes the
// generated declaration of the per-frame uniforms, `scene: SceneUniforms` at group 0 binding 0
// (src/gpu/contract.ts SCENE_UNIFORMS: its fields and their meaning are declared there).

// Colours are written as sRGB, like a colour picker gives them; lighting happens in linear
// space and the render target is an -srgb view, which encodes on store.
fn linearFromSrgb(c: vec3f) -> vec3f {
  return pow(c, vec3f(2.2));
}

fn modelToWorld(p: vec3f) -> vec3f {
  return (scene.model * vec4f(p, 1.0)).xyz;
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
  return p + (scene.eye.xyz - p) * amount;
}
