// A ground plane under the model: a faint grid that catches the shadow and fades into the
// backdrop (prepended: wgsl/render/common.wgsl, wgsl/render/shading.wgsl). Drawn as a 4-vertex strip.

// GROUND_EXTENT (in bounding radii) comes with the prelude: camera.ts fits the clip planes and
// the light's box to the same number (src/gpu/contract/render.ts).

struct VertexOut {
  @builtin(position) clip: vec4f,
  @location(0) world: vec3f,
}

@vertex
fn groundVertex(@builtin(vertex_index) i: u32) -> VertexOut {
  let corner = vec2f(f32(i & 1u), f32(i >> 1u)) * 2.0 - 1.0;
  let r = scene.eye.w * GROUND_EXTENT;
  let world = vec3f(scene.center.x + corner.x * r, scene.center.w, scene.center.z + corner.y * r);
  var out: VertexOut;
  out.clip = scene.viewProj * vec4f(world, 1.0);
  out.world = world;
  return out;
}

// Coverage of grid lines of this spacing, about one pixel wide whatever the distance.
fn gridLines(p: vec2f, spacing: f32) -> f32 {
  let q = p / spacing;
  let width = fwidth(q);
  let d = abs(fract(q - 0.5) - 0.5) / max(width, vec2f(1e-6));
  let line = 1.0 - min(min(d.x, d.y), 1.0);
  // Where cells shrink to a few pixels (far away, grazing) the lines would turn into moiré: fade them.
  return line * (1.0 - smoothstep(0.08, 0.3, max(width.x, width.y)));
}

@fragment
fn groundFragment(in: VertexOut) -> @location(0) vec4f {
  let r = scene.eye.w;
  // Grid spacing: a power of ten near a quarter of the model's radius, with a minor grid.
  let major = pow(10.0, round(log2(r * 0.5) / log2(10.0)));
  let rel = in.world.xz - scene.center.xz;
  let lines = max(gridLines(rel, major) * 0.5, gridLines(rel, major * 0.2) * 0.18);

  let up = vec3f(0.0, 1.0, 0.0);
  let shadow = shadowFactor(in.world, up);
  let base = linearFromSrgb(vec3f(0.25, 0.27, 0.31));
  let lit = base * (0.35 + 0.65 * shadow);
  let colour = mix(lit, linearFromSrgb(vec3f(0.42, 0.46, 0.53)), lines * (0.3 + 0.7 * shadow));

  // Fade out towards the edge of the plane so it has no visible border.
  let fade = 1.0 - smoothstep(0.15, 0.8, length(rel) / (r * GROUND_EXTENT));
  return vec4f(colour, fade);
}
