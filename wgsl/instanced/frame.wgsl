// The instanced tessellator drawn on its own (src/gpu/instanced/instanced.ts encodeDraw: tests, and any
// page without the demo renderer): a frame uniform and simple clay shading (prepended: the
// vertex function, wgsl/instanced/draw.wgsl).
//
//   frame (uniform, group 2): INST_FRAME: viewProj, lightViewProj, toLight, eye

// The struct and its binding are generated (src/gpu/instanced/buffer-layouts.ts INST_FRAME, INST_FRAME_GROUP).

struct VertexOut {
  @builtin(position) clip: vec4<f32>,
  @location(0) world: vec3<f32>,
  @location(1) normal: vec3<f32>,
}

@vertex
fn litVertex(@builtin(instance_index) instance: u32, @builtin(vertex_index) index: u32) -> VertexOut {
  let v = instancedVertex(instance, index);
  return VertexOut(frame.viewProj * vec4<f32>(v.pos, 1.0), v.pos, v.normal);
}

// Depth only, from the light: the shadow map pass re-evaluates the surface too (the point of
// comparing this tessellator with the compute one, which draws its stored mesh in every pass).
@vertex
fn shadowVertex(@builtin(instance_index) instance: u32, @builtin(vertex_index) index: u32) -> @builtin(position) vec4<f32> {
  return frame.lightViewProj * vec4<f32>(instancedVertex(instance, index).pos, 1.0);
}

@fragment
fn litFragment(in: VertexOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
  var n = normalize(in.normal);
  n = select(-n, n, front); // open surfaces: light the side that is seen
  let toEye = normalize(frame.eye.xyz - in.world);
  let h = normalize(frame.toLight.xyz + toEye);
  let albedo = select(vec3<f32>(0.28, 0.40, 0.56), vec3<f32>(0.70, 0.62, 0.52), front); // clay front, blue back
  let diffuse = max(dot(n, frame.toLight.xyz), 0.0);
  let c = albedo * (0.18 + 0.82 * diffuse) + vec3<f32>(0.12) * pow(max(dot(n, h), 0.0), 40.0);
  return vec4<f32>(c, 1.0);
}

