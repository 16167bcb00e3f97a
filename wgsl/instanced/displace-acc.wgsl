// An ACC surface at cage triangle t and 16.16 weights w, for the displaced vertex function
// (wgsl/instanced/displace.wgsl): the patch is the triangle's face (the lender's dispTri word
// 3t + 2; ACC refuses n-gons), its (u, v) linear in w as src/gpu/tess/face-params.ts inverts it: a
// quad's first fan triangle (c0, c1, c2) (u, v) = (w1 + w2, w2), its second (c0, c2, c3)
// (w1, w1 + w2); a triangle face (w1, w2). The tangents come back along w1, w2 (displacePoint's
// contract) by the chain rule: ∂P/∂w1 = Pu·∂u/∂w1 + Pv·∂v/∂w1, and so for w2.
fn triSurface(t: u32, w: vec3<u32>) -> SurfacePoint {
  let face = ccStatic[ccParams.offDispTri + 3u * t + 2u];
  let info = ccStatic[ccParams.offDispTri + 3u * t + 1u];
  let w1 = f32(w.y) / 65536.0;
  let w2 = f32(w.z) / 65536.0;
  if (dispTriWord_corners(info) != 4u) {
    let s = evalAccPatch(face, w1, w2);
    return SurfacePoint(s.pos, s.normal, s.du, s.dv);
  }
  if (dispTriWord_fan(info) == 1u) {
    let s = evalAccPatch(face, f32(w.y + w.z) / 65536.0, w2);
    return SurfacePoint(s.pos, s.normal, s.du, s.du + s.dv);
  }
  let s = evalAccPatch(face, w1, f32(w.y + w.z) / 65536.0);
  return SurfacePoint(s.pos, s.normal, s.du + s.dv, s.dv);
}
