// The tessellated mesh, lit and shadowed (prepended: wgsl/render/common.wgsl, wgsl/render/shading.wgsl).

// Patch colours: srcTri and patchKind (group 2), each vertex's source triangle and that
// triangle's patch kind + 1: src/gpu/contract/render.ts PATCH_KIND_GROUP, prepended.

struct VertexOut {
  @builtin(position) clip: vec4f,
  // Centroid: with MSAA a pixel on a contour is shaded once, and at its centre the position
  // would be extrapolated off the triangle, past the contour and under the surface, where the
  // shadow lookup finds the surface itself above it: a dark dot on every such pixel of an
  // occlusion contour. At the centroid of the covered samples it stays on the triangle.
  @location(0) @interpolate(perspective, centroid) world: vec3f,
  @location(1) @interpolate(perspective, centroid) normal: vec3f,
  // Patch colours: one-hot weights of the vertex's patch kind (regular, irregular quad, triangle,
  // crease), zero for the usual colours. Interpolated: a tessellated triangle whose vertices were
  // welded to neighbouring source triangles blends their colours (flat shading would take its
  // first vertex's and draw saw teeth along the patch boundaries).
  @location(2) patchWeights: vec4f,
}

// PATCH_SRGB (the prelude) holds the colours of the kinds, the legend's (src/gpu/contract/render.ts PATCH_COLOURS).
fn patchColour(w: vec4f) -> vec3f {
  let c = w.x * linearFromSrgb(PATCH_SRGB[0]) + w.y * linearFromSrgb(PATCH_SRGB[1])
    + w.z * linearFromSrgb(PATCH_SRGB[2]) + w.w * linearFromSrgb(PATCH_SRGB[3]);
  return c / max(dot(w, vec4f(1.0)), 1e-6);
}

fn litPlain(position: vec3f, normal: vec3f) -> VertexOut {
  let world = modelToWorld(position);
  var out: VertexOut;
  out.clip = scene.viewProj * vec4f(world, 1.0);
  out.world = world;
  out.normal = (scene.model * vec4f(normal, 0.0)).xyz;
  out.patchWeights = vec4f(0.0);
  return out;
}

// Where the vertex stage may read no storage buffers (WebGPU compatibility mode): no patch colours.
@vertex
fn litVertexPlain(@location(0) position: vec3f, @location(1) normal: vec3f) -> VertexOut {
  return litPlain(position, normal);
}

@vertex
fn litVertex(@builtin(vertex_index) index: u32, @location(0) position: vec3f, @location(1) normal: vec3f) -> VertexOut {
  var out = litPlain(position, normal);
  if (scene.viewport.w > 0.5 && index < arrayLength(&srcTri)) {
    let t = srcTri[index];
    if (t < arrayLength(&patchKind)) {
      let k = patchKind[t];
      out.patchWeights = select(vec4f(0.0), vec4f(1.0), vec4<u32>(k) == vec4<u32>(1u, 2u, 3u, 4u));
    }
  }
  return out;
}

// The surface's colour at a point seen with normal `n` (towards the viewer's side) and `albedo`,
// under the studio rig (wgsl/render/shading.wgsl), as clay or as metal (scene.look.x).
fn shade(world: vec3f, n: vec3f, toEye: vec3f, albedo: vec3f) -> vec3f {
  let l = scene.toLight.xyz;
  let ndl = max(dot(n, l), 0.0);
  // The shadow lookup is offset along the shading normal, which varies smoothly from pixel to
  // pixel. It was offset along the facet (from screen derivatives), but the facets of a fine
  // tessellation turn from one tiny triangle to the next, and where a shadow's edge crosses a
  // surface at a grazing angle (the pawn's head over its collar) the lookup followed them: a
  // grainy band of lit and dark pixels, in the factor-16 frame too (e2e/artifacts.spec.ts, pawn
  // adaptive Phong: one speckle there with the Phong α per edge; 0 now, and suzanne's adaptive
  // Phong 1 -> 0).
  let shadow = shadowFactor(world, n);
  let fill = fillDirection();
  let back = backDirection();
  let ndv = max(dot(n, toEye), 0.0);
  if (scene.look.x > 0.5) {
    // Metal: no diffuse; the studio reflected, by Schlick's Fresnel from the albedo as F0.
    let f = albedo + (vec3f(1.0) - albedo) * pow(1.0 - ndv, 5.0);
    let seen = studioRadiance(reflect(-toEye, n));
    let keySpecular = KEY * pow(max(dot(n, normalize(l + toEye)), 0.0), 180.0) * 1.5 * ndl;
    return f * (seen.sky + (seen.key + keySpecular) * shadow);
  }
  let diffuse = ambient(n) + KEY * ndl * shadow + FILL * max(dot(n, fill), 0.0) + BACK * max(dot(n, back), 0.0);
  let specular = KEY * pow(max(dot(n, normalize(l + toEye)), 0.0), 64.0) * 0.22 * ndl * shadow
    + BACK * pow(max(dot(n, normalize(back + toEye)), 0.0), 24.0) * 0.35 * max(dot(n, back), 0.0);
  return albedo * diffuse + specular;
}

@fragment
fn litFragment(in: VertexOut, @builtin(front_facing) front: bool) -> @location(0) vec4f {
  let toEye = normalize(scene.eye.xyz - in.world);
  // The facet's normal, for vertices whose normal is degenerate (a zero sum of faces).
  var faceNormal = normalize(cross(dpdx(in.world), dpdy(in.world)));
  faceNormal = select(-faceNormal, faceNormal, dot(faceNormal, toEye) >= 0.0);
  var n = faceNormal;
  var inside = 0.0;
  if (dot(in.normal, in.normal) > 1e-12) {
    n = normalize(in.normal);
    // Open surfaces show their inside: lit as seen, from the viewer's side (wgsl/render/common.wgsl
    // insideWeight: not where the tessellation folds over at a contour).
    inside = insideWeight(front, n, toEye);
    if (inside < 0.0) { discard; }
  }

  // Clay outside, a cooler tint inside open surfaces.
  var outsideAlbedo = linearFromSrgb(vec3f(0.86, 0.80, 0.72));
  var insideAlbedo = linearFromSrgb(vec3f(0.56, 0.66, 0.78));
  if (dot(in.patchWeights, vec4f(1.0)) > 0.01) {
    outsideAlbedo = patchColour(in.patchWeights);
    insideAlbedo = outsideAlbedo * 0.7;
  }
  var colour = vec3f(0.0);
  if (inside < 1.0) { colour += (1.0 - inside) * shade(in.world, towardsEye(n, toEye), toEye, outsideAlbedo); }
  if (inside > 0.0) { colour += inside * shade(in.world, towardsEye(-n, toEye), toEye, insideAlbedo); }
  return vec4f(toneMap(colour), 1.0);
}
