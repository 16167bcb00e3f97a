// Shared by every render and wire shader (the renderer prepends it). Before it comes the
// generated declaration of the per-frame uniforms, `scene: SceneUniforms` at group 0 binding 0
// (src/gpu/contract/render.ts SCENE_UNIFORMS: its fields and their meaning are declared there).

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

// How a fragment of a two-sided (open) surface is seen: -1 not at all (discard it), else the
// share of the inside (0 the outside, 1 the inside). The rasterizer's facing alone is not the
// answer: at an occlusion contour (a brow seen from above) the tessellated mesh folds over by a
// fraction of a pixel, and its back-facing triangles there stand in front of the front-facing
// ones. Drawn as an inside (flipped normal, inside tint, the underside's shadow) they made the
// dark dotted lines along suzanne's brows. Such a triangle's own surface normal
// `n` still faces the eye, or turns away from it by a sliver; a real inside, seen through an
// opening, faces away. So a back face whose normal turns away by less than INSIDE_FROM (a
// cosine) is dropped, as a closed surface's back faces are culled, and the inside's tint and
// light come in fully by INSIDE_TO, so an inside seen at a grazing angle has no seam.
const INSIDE_FROM: f32 = 0.05;
const INSIDE_TO: f32 = 0.2;
fn insideWeight(front: bool, n: vec3f, toEye: vec3f) -> f32 {
  let away = -dot(n, toEye);
  if (front) { return 0.0; }
  return select(smoothstep(INSIDE_FROM, INSIDE_TO, away), -1.0, away < INSIDE_FROM);
}

// A shading normal `n` seen from the eye's side: a normal that turns away from the eye loses
// that part (it is projected onto the plane across the view ray), so it shades as the contour
// does. Near a contour a coarse tessellation's front faces can carry normals that face away
// (the limit surface turns away there, its chord does not): lit as they are, they drew dark
// dots just inside occlusion contours.
fn towardsEye(n: vec3f, toEye: vec3f) -> vec3f {
  let m = n - min(dot(n, toEye), 0.0) * toEye;
  return select(n, normalize(m), dot(m, m) > 1e-12);
}
