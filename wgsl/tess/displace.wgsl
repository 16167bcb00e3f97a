// Displacement over the surface (issue 12), in the same pass that evaluates the surface: the
// weld and emit passes write surfaceAt(t, w) (wgsl/tess/outputs.wgsl), the surface module's
// evalSurface passed through displacePoint here, which moves it along its normal by the map:
//   P' = P + h·N,  h = (sample(uv) − dispMid)·dispScale,
//   N' = normalize(N − ∇h), ∇h the surface gradient of h from the surface's tangents.
// The CPU reference is src/subdiv/displace.ts (f64); the data layout and the seam rule are in
// src/gpu/tess/displacement-map.ts. Needs the tessellator's prelude and wgsl/tess/common.wgsl (params,
// staticBuf, cageBuf, SurfacePoint, the DispTriWord getters); nothing of the surface module.
//
// Parameters. Every surface gives its tangents along the triangle's own weights (SurfacePoint
// du = ∂P/∂w1, dv = ∂P/∂w2, moving w0 = 1 − w1 − w2 with them), and the uv is interpolated over
// the FACE's parameter as src/mesh/uv.ts does (OpenSubdiv's face-varying "linear all"): quads
// bilinear in the face's (u, v), other faces bilinear over the kite sub-faces of the regular
// n-gon (a triangle's kites give the linear interpolation). The uv's derivatives along the same
// w1, w2 come with it (dispUvFrame), so ∂h/∂w_i pairs with ∂P/∂w_i whatever the surface.
//
// The displaced normal. With T_i = ∂P/∂w_i projected into the plane of N and G their Gram
// matrix, ∇h = Σ (G⁻¹)_ij (∂h/∂w_j) T_i and N' = normalize(N − ∇h). Where N is the normal of the
// tangents (the exact surface) this is normalize((T1 + h1·N) × (T2 + h2·N)), the CPU reference's
// formula, in any parameterisation; where N is a shading normal (Phong's interpolated normals,
// Bezier ACC's tangent patches) it reduces to N when the height is flat, as it should. Like the
// reference it drops the h·∂N term (see src/subdiv/displace.ts for why and what it costs).

fn heightTexel(i: i32, j: i32) -> f32 {
  let W = i32(params.dispWidth);
  let H = i32(params.dispHeight);
  var ii = clamp(i, 0, W - 1);
  var jj = clamp(j, 0, H - 1);
  if (params.dispWrap == 0u) {
    ii = ((i % W) + W) % W;
    jj = ((j % H) + H) % H;
  }
  let idx = u32(jj * W + ii);
  if (params.dispBits == 8u) {
    let w = staticBuf[params.offHeightTexels + (idx >> 2u)];
    return f32((w >> (8u * (idx & 3u))) & 0xffu) / 255.0;
  }
  let w = staticBuf[params.offHeightTexels + (idx >> 1u)];
  return f32((w >> (16u * (idx & 1u))) & 0xffffu) / 65535.0;
}

// Bilinear sample at uv and its gradient d(sample)/d(u, v): src/mesh/heightmap.ts sampleHeight,
// with its texel centres (v = 0 at the image's bottom) and its gradient: the four texels' central
// differences blended with the bilinear weights (continuous across texel lines; the patch
// gradient's jumps there shaded as saw teeth). The weights are f32 arithmetic, not the sampler's
// (whose weights are quantised).
struct HeightSample { value: f32, grad: vec2<f32> }

fn centralDifference(i: i32, j: i32) -> vec2<f32> {
  return 0.5 * vec2<f32>(heightTexel(i + 1, j) - heightTexel(i - 1, j), heightTexel(i, j + 1) - heightTexel(i, j - 1));
}

fn sampleHeight(uv: vec2<f32>) -> HeightSample {
  let W = f32(params.dispWidth);
  let H = f32(params.dispHeight);
  let x = uv.x * W - 0.5;
  let y = (1.0 - uv.y) * H - 0.5;
  let x0 = floor(x);
  let y0 = floor(y);
  let fx = x - x0;
  let fy = y - y0;
  let i0 = i32(x0);
  let j0 = i32(y0);
  let t00 = heightTexel(i0, j0);
  let t10 = heightTexel(i0 + 1, j0);
  let t01 = heightTexel(i0, j0 + 1);
  let t11 = heightTexel(i0 + 1, j0 + 1);
  let value = (1.0 - fy) * ((1.0 - fx) * t00 + fx * t10) + fy * ((1.0 - fx) * t01 + fx * t11);
  let g = (1.0 - fy) * ((1.0 - fx) * centralDifference(i0, j0) + fx * centralDifference(i0 + 1, j0))
    + fy * ((1.0 - fx) * centralDifference(i0, j0 + 1) + fx * centralDifference(i0 + 1, j0 + 1));
  return HeightSample(value, vec2<f32>(g.x * W, -g.y * H));
}

// The uv at a point of triangle t and its derivatives along w1 and w2.
struct UvFrame { uv: vec2<f32>, d1: vec2<f32>, d2: vec2<f32> }

fn cornerUv(h: u32) -> vec2<f32> {
  let o = params.offCornerUvs + 2u * h;
  return vec2<f32>(cageBuf[o], cageBuf[o + 1u]);
}

// Bilinear over (a, b, c, d) at (s, t) = corners (0,0), (1,0), (1,1), (0,1), with ∂/∂s and ∂/∂t.
fn uvBilinear(a: vec2<f32>, b: vec2<f32>, c: vec2<f32>, d: vec2<f32>, s: f32, t: f32) -> UvFrame {
  let uv = (1.0 - s) * (1.0 - t) * a + s * (1.0 - t) * b + s * t * c + (1.0 - s) * t * d;
  return UvFrame(uv, (1.0 - t) * (b - a) + t * (c - d), (1.0 - s) * (d - a) + s * (c - b));
}

// Corner k of the regular n-gon the kites live in (src/gpu/tess/face-params.ts).
fn ngonCorner(n: u32, k: u32) -> vec2<f32> {
  let a = 6.283185307179586 * f32(k % n) / f32(n);
  return vec2<f32>(cos(a), sin(a));
}

fn dispUvFrame(t: u32, w: vec3<f32>) -> UvFrame {
  let h0 = staticBuf[params.offDispTri + 3u * t];
  let info = staticBuf[params.offDispTri + 3u * t + 1u];
  let n = dispTriWord_corners(info);
  let fan = dispTriWord_fan(info);
  if (n == 4u) {
    // The quad's (u, v) is linear in w (src/gpu/tess/face-params.ts): (c0, c1, c2) → (w1 + w2, w2),
    // (c0, c2, c3) → (w1, w1 + w2).
    let first = fan == 1u;
    let u = select(w.y, w.y + w.z, first);
    let v = select(w.y + w.z, w.z, first);
    let f = uvBilinear(cornerUv(h0), cornerUv(h0 + 1u), cornerUv(h0 + 2u), cornerUv(h0 + 3u), u, v);
    if (first) { return UvFrame(f.uv, f.d1, f.d1 + f.d2); }
    return UvFrame(f.uv, f.d1 + f.d2, f.d2);
  }
  if (n == 3u) {
    let c0 = cornerUv(h0);
    let c1 = cornerUv(h0 + 1u);
    let c2 = cornerUv(h0 + 2u);
    return UvFrame(w.x * c0 + w.y * c1 + w.z * c2, c1 - c0, c2 - c0);
  }
  // n ≥ 5: the point in the regular n-gon, its kite k (the corner nearest in angle) and (s, t)
  // by Newton on the kite's bilinear map, whose Jacobian then carries ∂/∂w into ∂/∂(s, t). The
  // triangle is (centre, fan, fan + 1) when centred (prepare.ts), the centre at the origin.
  let A0 = select(ngonCorner(n, 0u), vec2<f32>(0.0), dispTriWord_centred(info) == 1u);
  let q1 = ngonCorner(n, fan) - A0;
  let q2 = ngonCorner(n, fan + 1u) - A0;
  let p = A0 + w.y * q1 + w.z * q2;
  var centre = vec2<f32>(0.0);
  for (var j = 0u; j < n; j++) { centre += cornerUv(h0 + j); }
  centre /= f32(n);
  var k = 0u;
  var best = -2.0;
  for (var j = 0u; j < n; j++) {
    let d = dot(p, ngonCorner(n, j));
    if (d > best) { best = d; k = j; }
  }
  let A = ngonCorner(n, k);
  let B = 0.5 * (A + ngonCorner(n, k + 1u));
  let D = 0.5 * (A + ngonCorner(n, k + n - 1u));
  var s = 0.5;
  var tt = 0.5;
  var ds = vec2<f32>(0.0);
  var dt = vec2<f32>(0.0);
  for (var i = 0u; i < 12u; i++) {
    let f = (1.0 - s) * (1.0 - tt) * A + s * (1.0 - tt) * B + (1.0 - s) * tt * D - p;
    ds = (1.0 - tt) * (B - A) - tt * D;
    dt = (1.0 - s) * (D - A) - s * B;
    let det = ds.x * dt.y - ds.y * dt.x;
    if (det == 0.0) { break; }
    s -= (f.x * dt.y - f.y * dt.x) / det;
    tt -= (ds.x * f.y - ds.y * f.x) / det;
  }
  s = clamp(s, 0.0, 1.0);
  tt = clamp(tt, 0.0, 1.0);
  let a = cornerUv(h0 + k);
  let f = uvBilinear(a, 0.5 * (a + cornerUv(h0 + (k + 1u) % n)), centre, 0.5 * (a + cornerUv(h0 + (k + n - 1u) % n)), s, tt);
  // (∂s, ∂t)/∂w_i = J⁻¹ q_i with J = [∂p/∂s ∂p/∂t] (the kite's centre C is the origin).
  let det = ds.x * dt.y - ds.y * dt.x;
  if (det == 0.0) { return UvFrame(f.uv, vec2<f32>(0.0), vec2<f32>(0.0)); }
  let st1 = vec2<f32>(q1.x * dt.y - q1.y * dt.x, ds.x * q1.y - ds.y * q1.x) / det;
  let st2 = vec2<f32>(q2.x * dt.y - q2.y * dt.x, ds.x * q2.y - ds.y * q2.x) / det;
  return UvFrame(f.uv, st1.x * f.d1 + st1.y * f.d2, st2.x * f.d1 + st2.y * f.d2);
}

// s (a surface point of triangle t at weights wFixed, tangents along w1, w2) moved by the height
// map, its normal tilted by the height's gradient (for callers that evaluate the surface
// themselves).
fn displacePoint(t: u32, wFixed: vec3<u32>, s: SurfacePoint) -> SurfacePoint {
  let f = dispUvFrame(t, vec3<f32>(wFixed) / 65536.0);
  let hs = sampleHeight(f.uv);
  let h = (hs.value - params.dispMid) * params.dispScale;
  let h1 = params.dispScale * dot(hs.grad, f.d1);
  let h2 = params.dispScale * dot(hs.grad, f.d2);
  let n = s.normal;
  let a = s.du - dot(s.du, n) * n;
  let b = s.dv - dot(s.dv, n) * n;
  let g11 = dot(a, a);
  let g12 = dot(a, b);
  let g22 = dot(b, b);
  let det = g11 * g22 - g12 * g12;
  var nd = n;
  // Tangents that do not span the plane (a degenerate corner) give no gradient: N' = N.
  if (det > 1e-12 * g11 * g22 && det > 0.0) {
    let grad = ((g22 * h1 - g12 * h2) * a + (g11 * h2 - g12 * h1) * b) / det;
    let m = n - grad;
    nd = select(n, normalize(m), dot(m, m) > 0.0);
  }
  return SurfacePoint(s.pos + h * n, nd, s.du + h1 * n, s.dv + h2 * n);
}
