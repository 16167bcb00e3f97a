// The Catmull-Clark limit surface for the emit passes: evalSurface(t, wFixed) maps the cage
// triangle's barycentric point to its face (quads: (u,v) of the 0–2 split; triangles and
// n-gons: the kite sub-face k of the regular n-gon and its (s,t), as src/gpu/face-params.ts),
// then to its region (src/gpu/cc/build.ts: region (i, j) of the face's 2^d × 2^d split):
//   PATCH  a regular bicubic B-spline patch over 16 refined points, phantom rows/columns for
//          boundaries and infinitely sharp edges (notes §3.3), position and analytic normal;
//   SECTOR a sector of an extraordinary vertex's fan: after L = ceil(log2(1/max(a,b))) steps
//          the point lies on one of the regular sub-patches A, B, C of the fan's slice at step
//          L (notes §6.2); inside the last square (2^-7 of the face) a radial blend from the
//          vertex's limit to the exact ring round it (notes §6.3).
// Optionally (params.ccFlat) blends from the flat triangle of the corners' limit positions to
// the surface as the tess factor rises from 1 to 4.

const CC_NONE: u32 = 0xffffffffu;

fn ccP(p: u32) -> vec3<f32> {
  let o = select(params.offCtrl + 3u * (p - params.nVerts), 3u * p, p < params.nVerts);
  return vec3<f32>(cageBuf[o], cageBuf[o + 1u], cageBuf[o + 2u]);
}

fn ccBasis(t: f32) -> array<vec4<f32>, 2> {
  let s = 1.0 - t;
  let t2 = t * t;
  let t3 = t2 * t;
  let b = vec4<f32>(s * s * s, 3.0 * t3 - 6.0 * t2 + 4.0, -3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0, t3) / 6.0;
  let d = vec4<f32>(-0.5 * s * s, 0.5 * (3.0 * t2 - 4.0 * t), 0.5 * (-3.0 * t2 + 2.0 * t + 1.0), 0.5 * t2);
  return array<vec4<f32>, 2>(b, d);
}

// Bicubic B-spline patch of 16 points (row-major, row ~ y), all relative to point 5 (the
// corner (0,0): f32 precision of small patches), phantom mask bit j = side j (0: row 0, 1:
// column 3, 2: row 3, 3: column 0) reflected (notes §3.3: rows first, then columns).
fn ccBicubic(cp: ptr<function, array<vec3<f32>, 16>>, mask: u32, x: f32, y: f32) -> array<vec3<f32>, 3> {
  if ((mask & 1u) != 0u) { for (var c = 0u; c < 4u; c++) { (*cp)[c] = 2.0 * (*cp)[4u + c] - (*cp)[8u + c]; } }
  if ((mask & 4u) != 0u) { for (var c = 0u; c < 4u; c++) { (*cp)[12u + c] = 2.0 * (*cp)[8u + c] - (*cp)[4u + c]; } }
  if ((mask & 8u) != 0u) { for (var r = 0u; r < 4u; r++) { (*cp)[4u * r] = 2.0 * (*cp)[4u * r + 1u] - (*cp)[4u * r + 2u]; } }
  if ((mask & 2u) != 0u) { for (var r = 0u; r < 4u; r++) { (*cp)[4u * r + 3u] = 2.0 * (*cp)[4u * r + 2u] - (*cp)[4u * r + 1u]; } }
  let bx = ccBasis(x);
  let by = ccBasis(y);
  var p = vec3<f32>(0.0);
  var pu = vec3<f32>(0.0);
  var pv = vec3<f32>(0.0);
  for (var r = 0u; r < 4u; r++) {
    var row = vec3<f32>(0.0);
    var rowd = vec3<f32>(0.0);
    for (var c = 0u; c < 4u; c++) {
      let q = (*cp)[4u * r + c];
      row += bx[0][c] * q;
      rowd += bx[1][c] * q;
    }
    p += by[0][r] * row;
    pu += by[0][r] * rowd;
    pv += by[1][r] * row;
  }
  return array<vec3<f32>, 3>(p, pu, pv);
}

fn ccNormal(pu: vec3<f32>, pv: vec3<f32>) -> vec3<f32> {
  let n = cross(pu, pv);
  let l = length(n);
  return select(vec3<f32>(0.0, 0.0, 1.0), n / l, l > 0.0);
}

// rot_r of the unit square (build.ts rot): rot_1(x, y) = (y, 1 − x).
fn ccRot(r: u32, x: f32, y: f32) -> vec2<f32> {
  switch (r) {
    case 1u: { return vec2<f32>(y, 1.0 - x); }
    case 2u: { return vec2<f32>(1.0 - x, 1.0 - y); }
    case 3u: { return vec2<f32>(1.0 - y, x); }
    default: { return vec2<f32>(x, y); }
  }
}

fn ccRegularPatch(w0: u32, base: u32, x: f32, y: f32) -> SurfacePoint {
  var cp: array<vec3<f32>, 16>;
  let b = params.ccPatchIdx + 16u * base;
  let anchor = ccP(staticBuf[b + 5u]);
  for (var i = 0u; i < 16u; i++) { cp[i] = ccP(staticBuf[b + i]) - anchor; }
  let e = ccBicubic(&cp, (w0 >> 4u) & 15u, x, y);
  return SurfacePoint(anchor + e[0], ccNormal(e[1], e[2]));
}

// A fan's slice point (a, b), a, b ∈ −1..3, of sector i after step k (offsets from the
// anchor): own points a ≥ 1; (0, b ≥ 1) = sector i+1's (b, 0); (a, −1) = sector i−1's (1, a);
// (−1, b) = sector i+1's (b, 1); (0, 0) the centre. Sector indices wrap round an interior fan
// and clamp on a boundary fan (those points are then discarded by the phantom rule).
struct CCFan { ns: u32, n: u32, boundary: bool, base: u32 }

fn ccSlice(f: CCFan, i: u32, a: i32, b: i32) -> vec3<f32> {
  var s = i;
  var aa = a;
  var bb = b;
  if (a == 0 && b == 0) { return ccP(f.base + 12u * f.ns); }
  if (a == -1 && b == 0) {
    // The diagonal across (0, 1) from C: sector i+2's (1, 0) (round a valence-4 vertex).
    s = select((i + 2u) % f.n, min(i + 2u, f.n), f.boundary);
    aa = 1;
    bb = 0;
  } else if (a <= 0 && b >= 0) {
    s = select((i + 1u) % f.n, i + 1u, f.boundary);
    aa = b;
    bb = -a;
  } else if (b < 0) {
    s = select((i + f.n - 1u) % f.n, max(i, 1u) - 1u, f.boundary);
    aa = 1;
    bb = a;
  }
  if (aa < 1 || bb < 0 || aa > 3 || bb > 3) { return vec3<f32>(0.0); }
  return ccP(f.base + 12u * s + 4u * u32(aa - 1) + u32(bb));
}

fn ccFanWord(fan: u32, i: u32) -> u32 { return staticBuf[params.ccFans + 8u * fan + i]; }

// Sub-patch A (0), B (1) or C (2) of sector i at step k, at local (x, y); offsets from the anchor.
fn ccSubPatch(f: CCFan, fan: u32, i: u32, which: u32, x: f32, y: f32) -> array<vec3<f32>, 3> {
  var cp: array<vec3<f32>, 16>;
  let da = select(0, -1, which == 2u);
  let db = select(0, -1, which == 0u);
  for (var r = 0; r < 4; r++) {
    for (var c = 0; c < 4; c++) { cp[4 * r + c] = ccSlice(f, i, c + da, r + db); }
  }
  // Phantoms: A's bottom on axis i, C's left on axis i+1, when infinitely sharp.
  let sb = params.ccSectors + ccFanWord(fan, 3u);
  var mask = 0u;
  if (which == 0u && staticBuf[sb + 7u * i] == 1u) { mask = 1u; }
  if (which == 2u) {
    let nx = select((i + 1u) % f.n, i + 1u, f.boundary);
    if (staticBuf[sb + 7u * nx] == 1u) { mask = 8u; }
  }
  // Anchor the sum at the patch's corner (0,0) too.
  let o = cp[5];
  for (var j = 0u; j < 16u; j++) { cp[j] -= o; }
  var e = ccBicubic(&cp, mask, x, y);
  e[0] += o;
  return e;
}

fn ccSector(w0: u32, fan: u32, x: f32, y: f32) -> SurfacePoint {
  let sec = (w0 >> 12u) & 63u;
  let off = (w0 >> 8u) & 15u;
  let ab = ccRot((w0 >> 2u) & 3u, x, y) * exp2(-f32(off));
  let fw = ccFanWord(fan, 0u);
  let f = CCFan(fw & 255u, (fw >> 8u) & 255u, ((fw >> 16u) & 1u) == 1u, 0u);
  let D = (fw >> 20u) & 15u;
  let anchor = ccP(ccFanWord(fan, 1u));
  let lb = ccFanWord(fan, 5u);
  let m = max(ab.x, ab.y);
  // Step L: the first with max(a, b)·2^L ≥ 1 (exact powers of two in f32).
  var L = 1u;
  while (L < D && m * exp2(f32(L)) < 1.0) { L++; }
  var a = ab.x * exp2(f32(L));
  var b = ab.y * exp2(f32(L));
  let t = max(a, b);
  var blend = 1.0;
  if (t < 1.0) {
    // Inside the last square: the exact ring point on the ray, then the radial blend.
    if (t <= 0.0) {
      return SurfacePoint(ccP(lb), ccNormal(ccP(lb + 1u), ccP(lb + 2u)));
    }
    blend = pow(t, bitcast<f32>(ccFanWord(fan, 4u)));
    if (a >= b) { b = b / t; a = 1.0; } else { a = a / t; b = 1.0; }
  }
  let fk = CCFan(f.ns, f.n, f.boundary, ccFanWord(fan, 2u) + (L - 1u) * (12u * f.ns + 1u));
  var e: array<vec3<f32>, 3>;
  if (a >= 1.0 && b < 1.0) {
    e = ccSubPatch(fk, fan, sec, 0u, a - 1.0, b);
  } else if (a >= 1.0) {
    e = ccSubPatch(fk, fan, sec, 1u, a - 1.0, b - 1.0);
  } else {
    e = ccSubPatch(fk, fan, sec, 2u, a, b - 1.0);
  }
  let q = SurfacePoint(anchor + e[0], ccNormal(e[1], e[2]));
  if (blend >= 1.0) { return q; }
  let p0 = ccP(lb);
  let n0 = ccNormal(ccP(lb + 1u), ccP(lb + 2u));
  return SurfacePoint(p0 + blend * (q.pos - p0), normalize(mix(n0, q.normal, blend)));
}

fn ccEvalRegion(first: u32, dd: u32, k: u32, x0: f32, y0: f32) -> SurfacePoint {
  let side = 1u << dd;
  let fs = f32(side);
  let i = min(u32(floor(x0 * fs)), side - 1u);
  let j = min(u32(floor(y0 * fs)), side - 1u);
  let reg = first + k * side * side + j * side + i;
  let w0 = staticBuf[params.ccRegions + 2u * reg];
  let w1 = staticBuf[params.ccRegions + 2u * reg + 1u];
  let x = x0 * fs - f32(i);
  let y = y0 * fs - f32(j);
  if ((w0 & 3u) == 1u) {
    let l = ccRot((w0 >> 2u) & 3u, x, y);
    return ccRegularPatch(w0, w1, l.x, l.y);
  }
  return ccSector(w0, w1, x, y);
}

// Corner k of the regular n-gon whose table starts at `poly` (computed on the CPU in f64).
fn ccCorner(poly: u32, n: u32, k: u32) -> vec2<f32> {
  let o = params.ccPoly + 2u * (poly + k % n);
  return vec2<f32>(bitcast<f32>(staticBuf[o]), bitcast<f32>(staticBuf[o + 1u]));
}

// Sub-face k of an n-gon and (s,t): the kite round corner k of the regular n-gon, inverted by
// Newton (the map is bilinear and the kites are convex).
fn ccNgonParam(poly: u32, n: u32, fan: u32, w: vec3<f32>) -> vec3<f32> {
  let p = w.x * ccCorner(poly, n, 0u) + w.y * ccCorner(poly, n, fan) + w.z * ccCorner(poly, n, fan + 1u);
  if (length(p) < 1e-6) { return vec3<f32>(0.0, 1.0, 1.0); }
  // The kite of the corner nearest in angle (largest dot product).
  var k = 0u;
  var best = -2.0;
  for (var j = 0u; j < n; j++) {
    let d = dot(p, ccCorner(poly, n, j));
    if (d > best) { best = d; k = j; }
  }
  let A = ccCorner(poly, n, k);
  let B = 0.5 * (A + ccCorner(poly, n, k + 1u));
  let C = vec2<f32>(0.0);
  let D = 0.5 * (A + ccCorner(poly, n, k + n - 1u));
  var s = 0.5;
  var t = 0.5;
  for (var i = 0u; i < 12u; i++) {
    let f = (1.0 - s) * (1.0 - t) * A + s * (1.0 - t) * B + s * t * C + (1.0 - s) * t * D - p;
    let ds = (1.0 - t) * (B - A) + t * (C - D);
    let dt = (1.0 - s) * (D - A) + s * (C - B);
    let det = ds.x * dt.y - ds.y * dt.x;
    if (det == 0.0) { break; }
    s -= (f.x * dt.y - f.y * dt.x) / det;
    t -= (ds.x * f.y - ds.y * f.x) / det;
  }
  return vec3<f32>(f32(k), clamp(s, 0.0, 1.0), clamp(t, 0.0, 1.0));
}

fn evalSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint {
  let w = vec3<f32>(wFixed) / 65536.0;
  let first = staticBuf[params.ccTri + 3u * t];
  let info = staticBuf[params.ccTri + 3u * t + 1u];
  let n = info & 255u;
  let fan = (info >> 8u) & 0xfffffu;
  let dd = info >> 28u;
  var sp: SurfacePoint;
  if (n == 4u) {
    if (fan == 1u) {
      sp = ccEvalRegion(first, dd, 0u, w.y + w.z, w.z);
    } else {
      sp = ccEvalRegion(first, dd, 0u, w.y, w.y + w.z);
    }
  } else {
    let kst = ccNgonParam(staticBuf[params.ccTri + 3u * t + 2u], n, fan, w);
    sp = ccEvalRegion(first, dd, u32(kst.x), kst.y, kst.z);
  }
  if (params.ccFlat == 0u) { return sp; }
  // Flat baseline: the triangle of the corners' limit positions, blended to the surface by a
  // tess factor interpolated from the three edges (on an edge: that edge's factor, so both
  // triangles of the edge agree; at the corners flat and surface coincide).
  let v0 = triVert(t, 0u);
  let v1 = triVert(t, 1u);
  let v2 = triVert(t, 2u);
  let flat = w.x * factorPos(v0) + w.y * factorPos(v1) + w.z * factorPos(v2);
  let fn0 = w.x * factorNormal(v0) + w.y * factorNormal(v1) + w.z * factorNormal(v2);
  let e01 = w.x * w.y;
  let e12 = w.y * w.z;
  let e20 = w.z * w.x;
  let sum = e01 + e12 + e20;
  var F = 4.0;
  if (sum > 0.0) {
    F = (e01 * f32(edgeF(triEdge(t, 0u))) + e12 * f32(edgeF(triEdge(t, 1u))) + e20 * f32(edgeF(triEdge(t, 2u)))) / (65536.0 * sum);
  }
  let k = clamp((F - 1.0) / 3.0, 0.0, 1.0);
  let nm = mix(fn0, sp.normal, k);
  return SurfacePoint(mix(flat, sp.pos, k), select(sp.normal, normalize(nm), length(nm) > 1e-6));
}
