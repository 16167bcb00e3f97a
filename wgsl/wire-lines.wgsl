// Wireframe overlay: each triangle of the stored mesh becomes three lines, pulled straight from
// the index and position buffers (no expanded line buffer to allocate), drawn as a line-list
// with drawIndirect (prepended: render-common.wgsl).

@group(1) @binding(0) var<storage, read> indices: array<u32>;
@group(1) @binding(1) var<storage, read> positions: array<f32>;

@vertex
fn wireVertex(@builtin(vertex_index) i: u32) -> @builtin(position) vec4f {
  let triangle = i / 6u;
  // Line ends 0..5 walk the corners 0-1, 1-2, 2-0.
  let corner = ((i % 6u + 1u) / 2u) % 3u;
  let v = indices[triangle * 3u + corner];
  let p = vec3f(positions[3u * v], positions[3u * v + 1u], positions[3u * v + 2u]);
  return frame.viewProj * vec4f(pullTowardEye(modelToWorld(p), 1e-3), 1.0);
}

@fragment
fn wireFragment() -> @location(0) vec4f {
  return vec4f(linearFromSrgb(vec3f(0.10, 0.12, 0.16)), frame.viewport.z);
}
