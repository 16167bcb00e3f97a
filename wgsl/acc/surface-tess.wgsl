// The ACC surfaces (Bezier, Gregory, Pm ACC: wgsl/acc/surface.wgsl, built every frame by
// src/gpu/acc/patches.ts AccPatches) as the tessellator's surface: the triangle's ACC patch word
// (ACC_TRI_WORD, src/gpu/contract/tess.ts) gives its patch and its corners' patch parameters, and the
// patch parameter of the point is their interpolation by the point's weights (quads split on the
// 0–2 diagonal, triangles (u, v) = (w1, w2)): the same (face, u, v) as src/gpu/acc/patches.ts accFaceParam.
// The ACC patch table and control points live in the tessellator's own arenas (TESS_STATIC
// accPatches, TESS_CAGE accPoints: the control points copied there after every ACC build), read
// through the two accessors wgsl/acc/surface.wgsl asks for.

fn accPatchWord(i: u32) -> u32 { return staticBuf[params.offAccPatches + i]; }
fn accPt(i: u32) -> vec3<f32> { return cageVec3(params.offAccPoints + 4u * i); }

fn evalSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint {
  let w = vec3<f32>(wFixed) / 65536.0;
  let m = staticBuf[params.offAccTri + t];
  let c = accTriWord_corners(m);
  let uc = vec3<f32>(f32(accTriCorners_u0(c)), f32(accTriCorners_u1(c)), f32(accTriCorners_u2(c)));
  let vc = vec3<f32>(f32(accTriCorners_v0(c)), f32(accTriCorners_v1(c)), f32(accTriCorners_v2(c)));
  let a = evalAccPatch(accTriWord_face(m), dot(w, uc), dot(w, vc));
  // (u, v) is linear in w: ∂(u, v)/∂w_i = (u_i − u_0, v_i − v_0).
  let du = (uc.y - uc.x) * a.du + (vc.y - vc.x) * a.dv;
  let dv = (uc.z - uc.x) * a.du + (vc.z - vc.x) * a.dv;
  return SurfacePoint(a.pos, a.normal, du, dv);
}

// The surface without any display blend, which the factor rule looks at inside each triangle
// (wgsl/tess/factor-bulge.wgsl): this surface has none, so it is evalSurface.
fn unblendedSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint { return evalSurface(t, wFixed); }

// Its normal can turn inside an edge faster than between its ends (a hairpin of the limit
// surface): the factor rule samples it along each edge (wgsl/tess/factor-bulge.wgsl).
const SURFACE_NORMAL_TURNS: bool = true;
