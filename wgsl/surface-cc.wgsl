// The Catmull-Clark limit surface for the emit passes: evalSurface(t, wFixed) maps the cage
// triangle's barycentric point to its face (quads: (u,v) of the 0–2 split; triangles and
// n-gons: the kite sub-face k of the regular n-gon and its (s,t), as src/gpu/face-params.ts),
// walks the face's quadtree (src/gpu/cc/build.ts) to a regular bicubic patch and evaluates
// position and analytic normal. In the tiny region left round an irregular vertex it blends
// radially from the vertex's limit to the nearest regular patch. src/gpu/cc/evaluate.ts is the
// CPU twin. Optionally (params.ccFlat) blends from the flat triangle of the corners' limit
// positions to the surface as the tess factor rises from 1 to 4.

const CC_NO_NODE: u32 = 0xffffffffu;

fn ccCtrl(i: u32) -> vec3<f32> {
  let o = params.offCtrl + 3u * i;
  return vec3<f32>(cageBuf[o], cageBuf[o + 1u], cageBuf[o + 2u]);
}
fn ccNode(n: u32, i: u32) -> u32 { return staticBuf[params.ccNodes + 4u * n + i]; }

fn ccBasis(t: f32) -> array<vec4<f32>, 2> {
  let s = 1.0 - t;
  let t2 = t * t;
  let t3 = t2 * t;
  let b = vec4<f32>(s * s * s, 3.0 * t3 - 6.0 * t2 + 4.0, -3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0, t3) / 6.0;
  let d = vec4<f32>(-0.5 * s * s, 0.5 * (3.0 * t2 - 4.0 * t), 0.5 * (-3.0 * t2 + 2.0 * t + 1.0), 0.5 * t2);
  return array<vec4<f32>, 2>(b, d);
}

// Bicubic B-spline patch (16 points row-major from `base`, row ~ y): separable, rows in x
// first, then one cubic in y. Point 5 is absolute, the others are offsets from it (f32
// precision of small deep patches, src/gpu/cc/build.ts ANCHOR).
fn ccPatch(base: u32, x: f32, y: f32) -> SurfacePoint {
  let bx = ccBasis(x);
  let by = ccBasis(y);
  var p = vec3<f32>(0.0);
  var pu = vec3<f32>(0.0);
  var pv = vec3<f32>(0.0);
  for (var r = 0u; r < 4u; r++) {
    var row = vec3<f32>(0.0);
    var rowd = vec3<f32>(0.0);
    for (var c = 0u; c < 4u; c++) {
      let i = 4u * r + c;
      let q = select(ccCtrl(base + i), vec3<f32>(0.0), i == 5u);
      row += bx[0][c] * q;
      rowd += bx[1][c] * q;
    }
    p += by[0][r] * row;
    pu += by[0][r] * rowd;
    pv += by[1][r] * row;
  }
  let n = cross(pu, pv);
  let l = length(n);
  return SurfacePoint(ccCtrl(base + 5u) + p, select(vec3<f32>(0.0, 0.0, 1.0), n / l, l > 0.0));
}

struct CCLeaf { node: u32, x: f32, y: f32 }

fn ccDescend(root: u32, x0: f32, y0: f32) -> CCLeaf {
  var n = root;
  var x = x0;
  var y = y0;
  for (var guard = 0u; guard < 40u; guard++) {
    if ((ccNode(n, 0u) & 3u) != 0u) { break; }
    let i = select(0u, 1u, x >= 0.5);
    let j = select(0u, 1u, y >= 0.5);
    x = 2.0 * x - f32(i);
    y = 2.0 * y - f32(j);
    n = ccNode(n, 1u) + i + 2u * j;
  }
  return CCLeaf(n, x, y);
}

fn ccEvalRoot(root: u32, x0: f32, y0: f32) -> SurfacePoint {
  let leaf = ccDescend(root, x0, y0);
  let w0 = ccNode(leaf.node, 0u);
  if ((w0 & 3u) == 1u) { return ccPatch(ccNode(leaf.node, 1u), leaf.x, leaf.y); }
  // Blended leaf round an irregular vertex.
  let lim = ccNode(leaf.node, 1u);
  let p0 = ccCtrl(lim);
  let nc = cross(ccCtrl(lim + 1u), ccCtrl(lim + 2u));
  let n0 = select(vec3<f32>(0.0, 0.0, 1.0), normalize(nc), length(nc) > 0.0);
  let rc = (w0 >> 2u) & 3u;
  let alpha = f32(w0 >> 8u) / 4096.0;
  let cx = select(0.0, 1.0, rc == 1u || rc == 2u);
  let cy = select(0.0, 1.0, rc >= 2u);
  let a = abs(leaf.x - cx);
  let b = abs(leaf.y - cy);
  let t = max(a, b);
  if (t <= 0.0) { return SurfacePoint(p0, n0); }
  var sib: u32;
  var sx: f32;
  var sy: f32;
  if (a >= b) {
    sib = ccNode(leaf.node, 2u);
    sx = cx;
    sy = select(1.0 - b / t, b / t, cy == 0.0);
  } else {
    sib = ccNode(leaf.node, 3u);
    sy = cy;
    sx = select(1.0 - a / t, a / t, cx == 0.0);
  }
  if (sib == CC_NO_NODE) { return SurfacePoint(p0, n0); }
  let s = ccDescend(sib, sx, sy);
  if ((ccNode(s.node, 0u) & 3u) != 1u) { return SurfacePoint(p0, n0); }
  let q = ccPatch(ccNode(s.node, 1u), s.x, s.y);
  let f = pow(t, alpha);
  return SurfacePoint(p0 + f * (q.pos - p0), normalize(mix(n0, q.normal, f)));
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

// The cage vertices' limit positions and normals (cc-build.wgsl writes them where the factor
// rule reads: factorPos / factorNormal).

fn evalSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint {
  let w = vec3<f32>(wFixed) / 65536.0;
  let root = staticBuf[params.ccTri + 3u * t];
  let info = staticBuf[params.ccTri + 3u * t + 1u];
  let n = info & 255u;
  let fan = info >> 8u;
  var sp: SurfacePoint;
  if (n == 4u) {
    if (fan == 1u) {
      sp = ccEvalRoot(root, w.y + w.z, w.z);
    } else {
      sp = ccEvalRoot(root, w.y, w.y + w.z);
    }
  } else {
    let kst = ccNgonParam(staticBuf[params.ccTri + 3u * t + 2u], n, fan, w);
    sp = ccEvalRoot(root + u32(kst.x), kst.y, kst.z);
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
