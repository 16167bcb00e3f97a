// The instanced tessellator in the demo renderer's passes (src/gpu/instanced/instanced.ts drawShadow,
// drawLit, drawWire; src/gpu/render/renderer.ts SurfaceDrawer): the surface is evaluated again in each
// pass, shaded exactly as the renderer shades its stored mesh. Prepended: the vertex function
// (wgsl/instanced/draw.wgsl, with the surface), the renderer's scene uniform at group 2 binding 0,
// wgsl/render/common.wgsl, wgsl/render/shading.wgsl (its shadow map and sampler at group 2 bindings 1 and
// 2) and wgsl/render/lit.wgsl (its litFragment shades here; its patch-colour buffers, moved to group
// 3 bindings 10 and 11, clear of an ACC surface's 0 and 1, belong to its own litVertex and are
// not bound).

@vertex
fn instancedLitVertex(@builtin(instance_index) instance: u32, @builtin(vertex_index) index: u32) -> VertexOut {
  let v = instancedVertex(instance, index);
  let world = modelToWorld(v.pos);
  var out: VertexOut;
  out.clip = scene.viewProj * vec4f(world, 1.0);
  out.world = world;
  // Flat shading: no vertex normal, so litFragment shades each facet by its own (derivatives).
  out.normal = select((scene.model * vec4f(v.normal, 0.0)).xyz, vec3f(0.0), params.flatShading == 1u);
  // Patch colours: the kind of the patch (patchColourIndex comes with the surface: regular,
  // irregular quad or triangle on ACC; quad or triangle on Phong).
  out.patchWeights = vec4f(0.0);
  if (scene.viewport.w > 0.5) {
    out.patchWeights = select(vec4f(0.0), vec4f(1.0), vec4<u32>(patchColourIndex(v.patchId)) == vec4<u32>(0u, 1u, 2u, 3u));
  }
  return out;
}

@vertex
fn instancedShadowVertex(@builtin(instance_index) instance: u32, @builtin(vertex_index) index: u32) -> @builtin(position) vec4f {
  return scene.lightViewProj * vec4f(modelToWorld(instancedVertex(instance, index).pos), 1.0);
}

struct WireOut {
  @builtin(position) clip: vec4f,
  @location(0) alpha: f32,
}

// Wireframe: line ends 0..5 of pattern triangle i / 6 walk its edges 0-1, 1-2, 2-0 (as
// wgsl/render/wire-lines.wgsl does for the stored mesh), non-indexed, drawIndirect from the wire records.
// Both ends are evaluated (one call site in a loop) to fade edges only a few pixels long.
@vertex
fn instancedWireVertex(@builtin(instance_index) instance: u32, @builtin(vertex_index) i: u32) -> WireOut {
  let triangle = i / 6u;
  let edge = (i % 6u) / 2u;
  var ends: array<vec4f, 2>;
  for (var e = 0u; e < 2u; e++) {
    let corner = (edge + e) % 3u;
    let local = staticBuf[params.offPatternIdx + bucket.firstIndex + 3u * triangle + corner];
    let p = instancedVertex(instance, bucket.baseVertex + local).pos;
    ends[e] = scene.viewProj * vec4f(pullTowardEye(modelToWorld(p), 1e-3), 1.0);
  }
  let a = ends[0];
  let b = ends[1];
  let pixels = length((a.xy / max(a.w, 1e-6) - b.xy / max(b.w, 1e-6)) * scene.viewport.xy * 0.5);
  var out: WireOut;
  out.clip = select(a, b, i % 2u == 1u);
  out.alpha = scene.viewport.z * mix(0.15, 1.0, smoothstep(4.0, 16.0, pixels));
  return out;
}

@fragment
fn instancedWireFragment(in: WireOut) -> @location(0) vec4f {
  return vec4f(linearFromSrgb(vec3f(0.10, 0.12, 0.16)), in.alpha);
}
