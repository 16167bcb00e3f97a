// The instanced tessellator on an ACC surface (Bezier, Gregory or Pm ACC: src/gpu/acc/patches.ts builds
// the patches, wgsl/acc/surface.wgsl evaluates them; its two buffers are declared at group 3,
// bindings 0 and 1, by src/gpu/acc/patches.ts accBindingsWgsl, prepended with the evaluator). A patch is
// a cage face (ACC refuses n-gons, so there are no fan triangles), and its pattern point (i, j) at
// level P is the face parameter (u, v) = (i, j) / P exactly (quads: u along corner 0 → 1, v along
// 1 → 2, as src/gpu/tess/face-params.ts; triangles: the weights of corners 1 and 2, as
// src/gpu/acc/patches.ts accFaceParam).

fn patchSurface(p: u32, P: u32, i: u32, j: u32) -> SurfacePoint {
  let s = evalAccPatch(patchWord(p, 6u), f32(i) / f32(P), f32(j) / f32(P));
  return SurfacePoint(s.pos, s.normal, s.du, s.dv); // tangents along the patch's (u, v)
}

// Patch colours, the sample's "show irregular patches" (wgsl/render/instanced.wgsl;
// src/gpu/contract/render.ts PATCH_COLOURS order): a regular patch (a plain bicubic, ACC kind 0), an
// irregular quad (Bezier, Gregory or Pm ACC around an extraordinary vertex), a triangle.
fn patchColourIndex(p: u32) -> u32 {
  if (accPatches[2u * patchWord(p, 6u)] == 0u) { return 0u; }
  return select(1u, 2u, patchIsTri(p));
}

// What the factor rule reads at a cage vertex (wgsl/instanced/levels.wgsl edgeFactorRule): the
// cage position and vertex normal, as the compute tessellator's factor rule reads them on an ACC
// surface (src/gpu/tess/tessellator.ts: offFactorPos is the cage's for every surface but Catmull-Clark).
fn factorPoint(v: u32) -> FactorPoint { return FactorPoint(cagePos(v), cageNormal(v)); }
