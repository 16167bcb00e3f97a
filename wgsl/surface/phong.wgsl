// The Phong tessellation surface over the cage's vertex normals (src/gpu/surface/phong.ts is its CPU
// twin, and says why α is per edge). A surface module provides evalSurface for the emit passes
// of the tessellator.

// Boubekeur & Alexa 2008 as the quadratic Bézier triangle it is: the corners, and on each edge
// i → j the control point b_ij = (p_i + p_j)/2 + (α/2)((e·n_j) n_j − (e·n_i) n_i), e = p_j − p_i,
// with the edge's own α (phongAlpha).
fn phongEdgeControl(pi: vec3<f32>, ni: vec3<f32>, pj: vec3<f32>, nj: vec3<f32>, alpha: f32) -> vec3<f32> {
  let e = pj - pi;
  return 0.5 * (pi + pj) + (0.5 * alpha) * (dot(e, nj) * nj - dot(e, ni) * ni);
}

// The surface point at 16.16 barycentrics of cage triangle t: the one function the Catmull-Clark
// surface replaces.
fn evalSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint {
  let w = vec3<f32>(wFixed) / 65536.0;
  let v0 = triVert(t, 0u);
  let v1 = triVert(t, 1u);
  let v2 = triVert(t, 2u);
  let p0 = cagePos(v0);
  let p1 = cagePos(v1);
  let p2 = cagePos(v2);
  let n0 = cageNormal(v0);
  let n1 = cageNormal(v1);
  let n2 = cageNormal(v2);
  let b01 = phongEdgeControl(p0, n0, p1, n1, phongAlpha(t, 0u));
  let b12 = phongEdgeControl(p1, n1, p2, n2, phongAlpha(t, 1u));
  let b20 = phongEdgeControl(p2, n2, p0, n0, phongAlpha(t, 2u));
  // Half the partial derivatives along w0, w1, w2 (each weight on its own).
  let h0 = w.x * p0 + w.y * b01 + w.z * b20;
  let h1 = w.y * p1 + w.x * b01 + w.z * b12;
  let h2 = w.z * p2 + w.y * b12 + w.x * b20;
  // Σ w_k h_k is the point; the tangents along w1, w2 (w0 = 1 − w1 − w2 moving with them).
  let pos = w.x * h0 + w.y * h1 + w.z * h2;
  let n = w.x * n0 + w.y * n1 + w.z * n2;
  let len = length(n);
  return SurfacePoint(pos, select(n0, n / len, len > 0.0), 2.0 * (h1 - h0), 2.0 * (h2 - h0));
}

// The surface without any display blend, which the factor rule looks at inside each triangle
// (wgsl/tess/factor-bulge.wgsl): this surface has none, so it is evalSurface.
fn unblendedSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint { return evalSurface(t, wFixed); }

// Its normal is interpolated between the corners, so it turns along an edge no faster than between
// its ends (which the edge term sees): no turn term (wgsl/tess/factor-bulge.wgsl).
const SURFACE_NORMAL_TURNS: bool = false;
