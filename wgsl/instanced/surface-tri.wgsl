// The instanced tessellator's surface through the compute tessellator's evalSurface contract
// (Phong, wgsl/surface/phong.wgsl, appended after this): pattern point (i, j) of patch p at level
// P → its cage triangle and exact 16.16 weights (patchTriangle) → evalSurface.

fn patchSurface(p: u32, P: u32, i: u32, j: u32) -> SurfacePoint {
  let pt = patchTriangle(p, P, i, j);
  return evalSurface(pt.t, pt.w);
}

// Patch colours (wgsl/render/instanced.wgsl; src/gpu/contract/render.ts PATCH_COLOURS order): quad
// patches in the regular colour, triangle patches in the triangle colour.
fn patchColourIndex(p: u32) -> u32 { return select(0u, 2u, patchIsTri(p)); }

// What the factor rule reads at a cage vertex (wgsl/instanced/levels.wgsl edgeFactorRule): the
// cage position and vertex normal, as the compute tessellator's Phong factor rule reads them.
fn factorPoint(v: u32) -> FactorPoint { return FactorPoint(cagePos(v), cageNormal(v)); }

// The surface at cage triangle t and weights w, for the displaced vertex function
// (wgsl/instanced/displace.wgsl): evalSurface itself (its tangents are along w1, w2).
fn triSurface(t: u32, w: vec3<u32>) -> SurfacePoint { return evalSurface(t, w); }
