// Displacement in the instanced tessellator's vertex function (src/gpu/instanced/displace-vertex.ts says
// the design). Appended, with the group-3 bindings of the lending compute Tessellator (ccParams,
// ccStatic, ccCage: its Params, TESS_STATIC and TESS_CAGE arenas, whatever the surface) and
// wgsl/tess/displace.wgsl renamed onto them, to the modules of an InstancedTessellator made with
// displacement. The surface module gives `fn triSurface(t: u32, w: vec3<u32>) -> SurfacePoint`:
// the surface at cage triangle t and 16.16 weights w, tangents along w1, w2 (displacePoint's
// contract).

// The seam rule, as the compute tessellator's weld (wgsl/tess/weld.wgsl): a pattern point on a
// cage edge (one weight 0) or at a cage vertex (one weight ONE) is evaluated through the OWNER
// triangle of that edge or vertex (the lender's edgeOwner, vertexOwner: src/gpu/tess/prepare.ts), with
// the owner's weights made from the same integers: at a vertex, ONE at the owner's corner; on an
// edge, the weight x of the edge's higher vertex (its canonical parameter: both patches of the
// edge snap to the same points, so both hold the same x) given to the owner's corner at that
// vertex and ONE − x to the other. Both patches then evaluate the identical function of identical
// integers, so the two copies of every boundary point are bit-identical, whatever the uvs or
// normals of the two faces (UV seams, sharp creases).
fn ownerPoint(pt: PatchTriangle) -> PatchTriangle {
  let t = pt.t;
  let w = pt.w;
  for (var k = 0u; k < 3u; k++) {
    if (w[k] == ONE) {
      let owner = ccStatic[ccParams.offVertexOwner + triVert(t, k)];
      var ow = vec3<u32>(0u);
      ow[ownerWord_corner(owner)] = ONE;
      return PatchTriangle(ownerWord_tri(owner), ow);
    }
  }
  for (var k = 0u; k < 3u; k++) {
    if (w[k] == 0u) {
      // Edge i of triangle t runs from its corner i to corner i + 1: the side opposite corner k.
      let i = (k + 1u) % 3u;
      let a = triVert(t, i);
      let b = triVert(t, (i + 1u) % 3u);
      let x = select(w[i], w[(i + 1u) % 3u], b > a); // the weight of the higher vertex
      let hi = max(a, b);
      let owner = ccStatic[ccParams.offEdgeOwner + ccStatic[ccParams.offTriEdges + 3u * t + i]];
      let ot = ownerWord_tri(owner);
      let oi = ownerWord_corner(owner);
      let oj = (oi + 1u) % 3u;
      let atI = triVert(ot, oi) == hi;
      var ow = vec3<u32>(0u);
      ow[oi] = select(ONE - x, x, atI);
      ow[oj] = select(x, ONE - x, atI);
      return PatchTriangle(ot, ow);
    }
  }
  return pt;
}

// The vertex function's surface (wgsl/instanced/draw.wgsl instancedVertex): pattern point →
// cage triangle and weights → its owner → the surface there → displaced when the lender's
// dispOn says so.
fn vertexSurface(p: u32, P: u32, i: u32, j: u32) -> SurfacePoint {
  let pt = ownerPoint(patchTriangle(p, P, i, j));
  let s = triSurface(pt.t, pt.w);
  if (ccParams.dispOn == 0u) { return s; }
  return displacePoint(pt.t, pt.w, s);
}
