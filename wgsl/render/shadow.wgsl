// Shadow map pass: depth only, from the light (the renderer prepends wgsl/render/common.wgsl).

@vertex
fn shadowVertex(@location(0) position: vec3f) -> @builtin(position) vec4f {
  return scene.lightViewProj * vec4f(modelToWorld(position), 1.0);
}
