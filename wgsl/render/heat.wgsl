// The ACC error views' heat map (prepended: wgsl/render/common.wgsl and src/gpu/acc/heat.ts
// heatRenderWgsl): the tessellated mesh coloured by the error of each output vertex, which the
// error pass (wgsl/acc/heat.wgsl) wrote per vertex index, 2 f32 each (distance / diagonal,
// degrees). The value, not the colour, is interpolated across a triangle, so the colours between
// vertices are the ramp's own. Shaded half-Lambert without shadows, as the NVIDIA sample does in
// its error modes: the colour must stay readable against the legend on every side of the model.

// heatValues and heat (group 2): src/gpu/contract/render.ts HEAT_RENDER_GROUP, prepended.

struct HeatOut {
  @builtin(position) clip: vec4f,
  // Centroid: on a contour's pixels, a position on the triangle (wgsl/render/lit.wgsl's VertexOut).
  @location(0) @interpolate(perspective, centroid) world: vec3f,
  @location(1) @interpolate(perspective, centroid) normal: vec3f,
  // The value as a fraction of the range (0..1 and beyond).
  @location(2) value: f32,
}

// HEAT_SRGB: blue at 0, green at 1/2, red at 1 and above (src/gpu/acc/heat.ts HEAT_RAMP, the legend's).
fn heatColour(x: f32) -> vec3f {
  let t = clamp(x, 0.0, 1.0) * 2.0;
  if (t < 1.0) { return mix(linearFromSrgb(HEAT_SRGB[0]), linearFromSrgb(HEAT_SRGB[1]), t); }
  return mix(linearFromSrgb(HEAT_SRGB[1]), linearFromSrgb(HEAT_SRGB[2]), t - 1.0);
}

@vertex
fn heatVertex(@builtin(vertex_index) index: u32, @location(0) position: vec3f, @location(1) normal: vec3f) -> HeatOut {
  let world = modelToWorld(position);
  var out: HeatOut;
  out.clip = scene.viewProj * vec4f(world, 1.0);
  out.world = world;
  out.normal = (scene.model * vec4f(normal, 0.0)).xyz;
  let k = 2u * index + min(heat.view, 1u);
  out.value = select(0.0, heatValues[k] / max(heat.range, 1e-30), k < arrayLength(&heatValues));
  return out;
}

@fragment
fn heatFragment(in: HeatOut, @builtin(front_facing) front: bool) -> @location(0) vec4f {
  let toEye = normalize(scene.eye.xyz - in.world);
  var n = normalize(cross(dpdx(in.world), dpdy(in.world)));
  n = select(-n, n, dot(n, toEye) >= 0.0);
  if (dot(in.normal, in.normal) > 1e-12) {
    n = normalize(in.normal);
    // The inside of an open surface, lit from the viewer's side (wgsl/render/common.wgsl insideWeight).
    let inside = insideWeight(front, n, toEye);
    if (inside < 0.0) { discard; }
    n = towardsEye(select(n, -n, inside > 0.5), toEye);
  }
  let halfLambert = 0.5 * dot(n, scene.toLight.xyz) + 0.5;
  return vec4f(heatColour(in.value) * (0.25 + 0.75 * halfLambert), 1.0);
}
