// The Phong tessellation surface over the cage's vertex normals (src/gpu/phong.ts is its CPU
// twin). A surface module provides evalSurface for the emit passes of the tessellator.

// Boubekeur & Alexa 2008: project the linear point onto the three vertex tangent planes,
// interpolate the projections, blend with α. The one function the Catmull-Clark surface
// replaces.
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
  let p = w.x * p0 + w.y * p1 + w.z * p2;
  let q0 = p - dot(p - p0, n0) * n0;
  let q1 = p - dot(p - p1, n1) * n1;
  let q2 = p - dot(p - p2, n2) * n2;
  let phong = w.x * q0 + w.y * q1 + w.z * q2;
  let n = w.x * n0 + w.y * n1 + w.z * n2;
  let len = length(n);
  // Tangents along w1, w2: ∂p = p_i − p0, ∂q_j = ∂p − (∂p·n_j) n_j, ∂phong = q_i − q0 + Σ w_j ∂q_j.
  let e1 = p1 - p0;
  let e2 = p2 - p0;
  let dq1 = e1 - (w.x * dot(e1, n0) * n0 + w.y * dot(e1, n1) * n1 + w.z * dot(e1, n2) * n2);
  let dq2 = e2 - (w.x * dot(e2, n0) * n0 + w.y * dot(e2, n1) * n1 + w.z * dot(e2, n2) * n2);
  let du = mix(e1, q1 - q0 + dq1, PHONG_ALPHA);
  let dv = mix(e2, q2 - q0 + dq2, PHONG_ALPHA);
  return SurfacePoint(mix(p, phong, PHONG_ALPHA), select(n0, n / len, len > 0.0), du, dv);
}

// The surface without any display blend, which the factor rule looks at inside each triangle
// (factor-bulge.wgsl): this surface has none, so it is evalSurface.
fn unblendedSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint { return evalSurface(t, wFixed); }
