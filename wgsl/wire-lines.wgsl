// Wireframe overlay: each triangle of the stored mesh becomes three lines, pulled straight from
// the index and position buffers (no expanded line buffer to allocate), drawn as a line-list
// with drawIndirect (prepended: render-common.wgsl).

@group(1) @binding(0) var<storage, read> indices: array<u32>;
@group(1) @binding(1) var<storage, read> positions: array<f32>;

struct VertexOut {
  @builtin(position) clip: vec4f,
  @location(0) alpha: f32,
}

fn cornerClip(triangle: u32, corner: u32) -> vec4f {
  let v = indices[triangle * 3u + corner];
  let p = vec3f(positions[3u * v], positions[3u * v + 1u], positions[3u * v + 2u]);
  return scene.viewProj * vec4f(pullTowardEye(modelToWorld(p), 1e-3), 1.0);
}

@vertex
fn wireVertex(@builtin(vertex_index) i: u32) -> VertexOut {
  let triangle = i / 6u;
  // Line ends 0..5 walk the edges 0-1, 1-2, 2-0.
  let edge = (i % 6u) / 2u;
  let end = i % 2u;
  let a = cornerClip(triangle, edge);
  let b = cornerClip(triangle, (edge + 1u) % 3u);
  // Edges only a few pixels long would paint the surface solid: fade them out, so a dense
  // tessellation reads as a texture of its density rather than a black blot.
  let pixels = length((a.xy / max(a.w, 1e-6) - b.xy / max(b.w, 1e-6)) * scene.viewport.xy * 0.5);
  var out: VertexOut;
  out.clip = select(a, b, end == 1u);
  out.alpha = scene.viewport.z * mix(0.15, 1.0, smoothstep(4.0, 16.0, pixels));
  return out;
}

@fragment
fn wireFragment(in: VertexOut) -> @location(0) vec4f {
  return vec4f(linearFromSrgb(vec3f(0.10, 0.12, 0.16)), in.alpha);
}
