// Wireframe overlay: each triangle of the stored mesh becomes three lines, pulled straight from
// the index and position buffers (no expanded line buffer to allocate), drawn as a line-list
// with drawIndirect (prepended: wgsl/render/common.wgsl).

// indices and positions (group 1): src/gpu/contract/render.ts WIRE_LINES_GROUP, prepended.

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
  let c = cornerClip(triangle, (edge + 2u) % 3u);
  // Edges only a few pixels long would paint the surface solid: fade them out, so a dense
  // tessellation reads as a texture of its density rather than a black blot. A sliver's long
  // edges fade with it (its width, twice its area over its longest side, in pixels): at the
  // adaptive factors' density the gap strips' slivers otherwise stand out as dark scratches.
  let half = scene.viewport.xy * 0.5;
  let sa = a.xy / max(a.w, 1e-6) * half;
  let sb = b.xy / max(b.w, 1e-6) * half;
  let sc = c.xy / max(c.w, 1e-6) * half;
  let pixels = length(sa - sb);
  let ab = sb - sa;
  let ac = sc - sa;
  let longest = max(max(pixels, length(ac)), length(sc - sb));
  let width = abs(ab.x * ac.y - ab.y * ac.x) / max(longest, 1e-6);
  var out: VertexOut;
  out.clip = select(a, b, end == 1u);
  out.alpha = scene.viewport.z * mix(0.15, 1.0, smoothstep(4.0, 16.0, min(pixels, 2.0 * width)));
  return out;
}

@fragment
fn wireFragment(in: VertexOut) -> @location(0) vec4f {
  return vec4f(linearFromSrgb(vec3f(0.10, 0.12, 0.16)), in.alpha);
}
