// The instanced tessellator on the exact Catmull-Clark limit surface (src/gpu/instanced/surface-cc.ts).
//
// The evaluator is the compute tessellator's own (src/gpu/cc/shaders.ts CC_SURFACE_WGSL:
// wgsl/cc/surface.wgsl evalSurface and what it includes), appended after this file with its
// module-scope names moved clear of this tessellator's (src/gpu/instanced/surface-cc.ts ccEvaluatorWgsl: params →
// ccParams, staticBuf → ccStatic, cageBuf → ccCage, evalSurface → ccEvalSurface, and the
// wgsl/tess/common.wgsl accessors it calls → the cc-prefixed ones below). It reads the buffers of a
// compute Tessellator with the Catmull-Clark surface for the same prepared mesh (borrowed, as
// src/gpu/acc/error.ts does), bound here in group 3:
//   ccParams  its Params uniform (src/gpu/contract/tess.ts TESS_PARAMS: where its tables lie)
//   ccStatic  its TESS_STATIC arena (the Catmull-Clark tables: regions, fans, patch indices)
//   ccCage    its TESS_CAGE arena (the refined points and limits its patch build writes)
//   ccWork    its TESS_WORK arena: read by the flat-baseline branch of evalSurface only, which
//             never runs here (the borrowed tessellator has flatBaseline off: checked in setMesh),
//             but is compiled, so bound
// Storage buffers per stage: this tessellator's 3 (group 0) + these 3 = 6 in the vertex stage,
// 8 in the headless compute pass (its two outputs): core WebGPU's minimum of 8 per stage.

// Group 3's bindings (ccParams, ccStatic, ccCage, ccWork) are generated: src/gpu/instanced/buffer-layouts.ts INST_SURFACE_GROUP.

// wgsl/tess/common.wgsl's accessors over the borrowed buffers (the same expressions).
fn ccTriVert(t: u32, i: u32) -> u32 { return ccStatic[ccParams.offTriVerts + 3u * t + i]; }
fn ccTriEdge(t: u32, i: u32) -> u32 { return ccStatic[ccParams.offTriEdges + 3u * t + i]; }
fn ccCageVec3(o: u32) -> vec3<f32> { return vec3<f32>(ccCage[o], ccCage[o + 1u], ccCage[o + 2u]); }
fn ccFactorPos(v: u32) -> vec3<f32> { return ccCageVec3(ccParams.offFactorPos + 3u * v); }
fn ccFactorNormal(v: u32) -> vec3<f32> { return ccCageVec3(ccParams.offFactorNormal + 3u * v); }
fn ccEdgeF(e: u32) -> u32 { return ccWork[ccParams.offEdgeF + e]; }

// Pattern point (i, j) of patch p at level P → its cage triangle and exact 16.16 weights
// (patchTriangle: the quad's two triangles map back to the face's (u, v) as wgsl/cc/surface.wgsl's
// evalSurface reads them) → the exact limit there.
fn patchSurface(p: u32, P: u32, i: u32, j: u32) -> SurfacePoint {
  let pt = patchTriangle(p, P, i, j);
  return ccEvalSurface(pt.t, pt.w);
}

// Patch colours (wgsl/render/instanced.wgsl; src/gpu/contract/render.ts PATCH_COLOURS order): a quad
// that is one regular bicubic patch of the exact surface (region depth 0 in its CcTriWord:
// src/gpu/cc/build.ts) in the regular colour, any other quad (at an extraordinary vertex, next to
// a triangle, on a crease that needs refinement) in the irregular one, triangle patches
// (triangles and n-gons' fans) in the triangle colour (src/app/instanced-view.ts counts the same).
fn patchColourIndex(p: u32) -> u32 {
  if (patchIsTri(p)) { return 2u; }
  let info = ccStatic[ccParams.ccTri + 3u * patchWord(p, 0u) + 1u];
  return select(1u, 0u, ccTriWord_depth(info) == 0u);
}

// What the factor rule reads at a cage vertex (wgsl/instanced/levels.wgsl edgeFactorRule): the
// limit position and normal there, written by the lending tessellator's patch build, as its own
// factor rule reads them.
fn factorPoint(v: u32) -> FactorPoint { return FactorPoint(ccFactorPos(v), ccFactorNormal(v)); }

// The surface at cage triangle t and weights w, for the displaced vertex function
// (wgsl/instanced/displace.wgsl): the compute tessellator's evaluator (tangents along w1, w2).
fn triSurface(t: u32, w: vec3<u32>) -> SurfacePoint { return ccEvalSurface(t, w); }
