// The Catmull-Clark limit surface for the emit passes: evalSurface(t, wFixed) maps the cage
// triangle's barycentric point to its face (quads: (u,v) of the 0–2 split; triangles and
// n-gons: the kite sub-face k of the regular n-gon and its (s,t), as src/gpu/tess/face-params.ts),
// then to its region (src/gpu/cc/build.ts: region (i, j) of the face's 2^d × 2^d split):
//   PATCH  a regular bicubic B-spline patch over 16 refined points, phantom rows/columns for
//          boundaries and infinitely sharp edges (OpenSubdiv's phantom points), position and analytic normal;
//          or a single-crease patch: one semi-sharp crease on its x = 0 side, the closed-form
//          change of basis across it (wgsl/cc/crease-basis.wgsl; Nießner, Loop, Greiner 2012);
//   SECTOR a sector of an extraordinary vertex's fan: after L = ceil(log2(1/max(a,b))) steps
//          the point lies on one of the regular sub-patches A, B, C of the fan's slice at step
//          L (src/gpu/cc/build.ts, "2. Fans"), A and C single-crease patches while a semi-sharp
//          axis beside them is still sharp at step L; inside the last square (2^-7 of the face) a
//          radial blend from the vertex's limit to the exact ring round it.
// Optionally (FLAT_BASELINE) blends from the flat triangle of the corners' limit positions to
// the surface as the tess factor rises from 1 to 4.
//
// What a cage's surface has, as override constants (SurfaceScheme.specialise,
// src/gpu/surface/registry.ts): a pipeline made for a cage of quads alone carries no n-gon
// parametrisation, one without single-crease patches no crease basis, one without boundaries or
// infinitely sharp edges no phantom points, one whose fans keep every step (CC_ODD_SLICES) no
// sub-patches made again; FLAT_BASELINE is the compute tessellator's
// flatBaseline option (off by default: the exact limit, as the instanced tessellator and the
// error views take this code). Not a uniform: a shader pays for the code it carries as well as
// for the code it runs (registers, occupancy; on a software GPU the compiled size is most of the
// cost). The case defaults take every cage.
override CC_NGONS: bool = true;
override CC_CREASE_PATCHES: bool = true;
override CC_PHANTOMS: bool = true;
override FLAT_BASELINE: bool = false;
override CC_ODD_SLICES: bool = true;

fn ccBasis(t: f32) -> array<vec4<f32>, 2> {
  let s = 1.0 - t;
  let t2 = t * t;
  let t3 = t2 * t;
  let b = vec4<f32>(s * s * s, 3.0 * t3 - 6.0 * t2 + 4.0, -3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0, t3) / 6.0;
  let d = vec4<f32>(-0.5 * s * s, 0.5 * (3.0 * t2 - 4.0 * t), 0.5 * (-3.0 * t2 + 2.0 * t + 1.0), 0.5 * t2);
  return array<vec4<f32>, 2>(b, d);
}

// A bicubic B-spline patch of 16 points (row-major, row ~ y) is summed row by row as its
// points are read, with no array of them: its weights (value and derivative, per column in x
// and per row in y) carry the phantom points instead. Phantom mask bit j = side j (0: row 0,
// 1: column 3, 2: row 3, 3: column 0) is OpenSubdiv's reflection, row 0 = 2·row 1 − row 2 and
// so on, which is linear, so it folds into the weights: the phantom row's weight moves to the
// two rows it is made of (+2, −1), and the phantom points themselves get weight 0.
struct CCWeights { x: vec4<f32>, dx: vec4<f32>, y: vec4<f32>, dy: vec4<f32> }

fn ccFoldLow(w: vec4<f32>) -> vec4<f32> { return vec4<f32>(0.0, w.y + 2.0 * w.x, w.z - w.x, w.w); }
fn ccFoldHigh(w: vec4<f32>) -> vec4<f32> { return vec4<f32>(w.x, w.y - w.w, w.z + 2.0 * w.w, 0.0); }

// The weights are given (value, d/dx per column; value, d/dy per row): ccBasis, or across a
// semi-sharp crease the crease basis's (ccEvalRegion).
fn ccWeights(bx: array<vec4<f32>, 2>, by: array<vec4<f32>, 2>, mask: u32) -> CCWeights {
  var w = CCWeights(bx[0], bx[1], by[0], by[1]);
  if (!CC_PHANTOMS) { return w; }
  if ((mask & 1u) != 0u) { w.y = ccFoldLow(w.y); w.dy = ccFoldLow(w.dy); }
  if ((mask & 4u) != 0u) { w.y = ccFoldHigh(w.y); w.dy = ccFoldHigh(w.dy); }
  if ((mask & 8u) != 0u) { w.x = ccFoldLow(w.x); w.dx = ccFoldLow(w.dx); }
  if ((mask & 2u) != 0u) { w.x = ccFoldHigh(w.x); w.dx = ccFoldHigh(w.dx); }
  return w;
}

// The running sum: position and the two derivatives, of points relative to point 5 (the
// corner (0,0): f32 precision of small patches).
struct CCSum { p: vec3<f32>, pu: vec3<f32>, pv: vec3<f32> }

fn ccNormal(pu: vec3<f32>, pv: vec3<f32>) -> vec3<f32> {
  let n = cross(pu, pv);
  let l = length(n);
  return select(vec3<f32>(0.0, 0.0, 1.0), n / l, l > 0.0);
}

// Tangents along (x, y) from tangents along rot_r(x, y) (pu, pv): the chain rule through ccRot.
// Rotations only, so the normal pu × pv is the same either way.
fn ccRotTangents(r: u32, pu: vec3<f32>, pv: vec3<f32>) -> array<vec3<f32>, 2> {
  switch (r) {
    case 1u: { return array<vec3<f32>, 2>(-pv, pu); }
    case 2u: { return array<vec3<f32>, 2>(-pu, -pv); }
    case 3u: { return array<vec3<f32>, 2>(pv, -pu); }
    default: { return array<vec3<f32>, 2>(pu, pv); }
  }
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

// The fans' slices (src/gpu/cc/build.ts, wgsl/cc/build.wgsl) hold per step k = 1..D the centre
// and every sector's 12 points (a, b), a ∈ 1..3, b ∈ 0..3 of its frame, as offsets from the
// fan's anchor: patch-major, so that a point of sector i at step L is one bicubic of 16 points
// read as they are, whatever L (the slice kernel made them once per rebuild, not once per vertex).
// A fan over the memory bound keeps its odd steps' sector points only: an even step's sub-patch
// is made again from the step before (ccDerivedSum).
// Sub-patch A (0: [1,2]×[0,1]), B (1: [1,2]²) or C (2: [0,1]×[1,2]) of sector i after step
// L ≥ 1, by where its points lie: the 12 points of sectors i (own), i+1, i−1, i+2 at that step,
// the centre, and the grid offset of its control point 0 (da, db).
struct CCSubPatch { own: u32, next: u32, prev: u32, next2: u32, centre: u32, da: i32, db: i32 }

fn ccSubPatchOf(f: CCFan, i: u32, L: u32, which: u32) -> CCSubPatch {
  let step = ccSliceStepBase(f, L);
  return CCSubPatch(step + 12u * i, step + 12u * ccNb(f, i, 1), step + 12u * ccNb(f, i, -1), step + 12u * ccNb(f, i, 2),
    f.base + L - 1u, select(0, -1, which == 2u), select(0, -1, which == 0u));
}

// Control point k (row-major, row ~ y) of the sub-patch: its point index. Grid point (a, b),
// a, b ∈ −1..3: own a ≥ 1, at 4(a − 1) + b of the sector's 12 (a boundary's pseudo-sector has
// its axis points 0, 4, 8 only); (0, 0) the centre; (0, b ≥ 1) = sector i+1's (b, 0); (−1, b ≥ 1)
// = sector i+1's (b, 1); (a, −1) = sector i−1's (1, a); (−1, 0) = sector i+2's (1, 0) (across the
// valence-4 (0, 1)).
fn ccSubPatchPoint(s: CCSubPatch, k: u32) -> u32 {
  let a = i32(k % 4u) + s.da;
  let b = i32(k / 4u) + s.db;
  // Selects, not early returns: one straight run of code per point (cheaper where a shader
  // compiler runs every branch under a mask, as SwiftShader does).
  var r = select(s.next2, s.centre, a == 0);
  r = select(r, s.next + u32(4 * (b - 1) - a), b >= 1);
  r = select(r, s.own + u32(4 * (a - 1) + b), a >= 1);
  return select(r, s.prev + u32(a), b < 0);
}

// Every region is evaluated as ONE bicubic B-spline patch of 16 points, whatever its kind:
//   PATCH   its 16 point indices at word w1 of patchIdx (phantom mask and single crease in w0);
//   SECTOR  sub-patch A, B or C of its sector at step L, the indices computed from the slices'
//           layout (ccSubPatchPoint).
// The kinds differ only in where the points are and in the frame, so each kind sets up its
// (x, y), weights and point source, and the 16-point sum is written once: a vertex costs one
// gather and one sum, and a workgroup whose threads fall in both kinds runs the sum once.
struct CCRegionEval {
  regular: bool,
  base: u32,         // PATCH: word of its 16 indices in staticBuf
  sub: CCSubPatch,   // SECTOR: where its sub-patch's points are
  origin: vec3<f32>, // what the points are offsets from (a fan's anchor; 0 for cage/refined points)
}

// Point indices q..q+3 (a row) of the region's patch. A branch, not a select: a patch's row is
// four loads, and only a sector's thread pays for the sub-patch's index arithmetic.
fn ccRegionRow(r: CCRegionEval, q: u32) -> vec4<u32> {
  if (r.regular) { return vec4<u32>(staticBuf[r.base + q], staticBuf[r.base + q + 1u], staticBuf[r.base + q + 2u], staticBuf[r.base + q + 3u]); }
  return vec4<u32>(ccSubPatchPoint(r.sub, q), ccSubPatchPoint(r.sub, q + 1u), ccSubPatchPoint(r.sub, q + 2u), ccSubPatchPoint(r.sub, q + 3u));
}

// Sub-patch `which` of sector i at an odd fan's even step L, summed with the weights w: its 16
// points are not in memory, so the sectors that hold them (i, i + 1, and i − 1 for A, i + 2 for C;
// B reads neither) are stepped again from the stored step L − 1, one at a time (one copy of the
// step in the shader), each point weighted as it is made. The points are offsets from the fan's
// anchor (the sum's origin).
fn ccDerivedSum(f: CCFan, sub: CCRegionEval, L: u32, i: u32, which: u32, w: CCWeights) -> CCSum {
  var e = CCSum(vec3<f32>(0.0), vec3<f32>(0.0), vec3<f32>(0.0));
  let centre = ccP(f.base + L - 1u);
  for (var d = 0; d < 4; d++) {
    if ((d == 2 && which != 0u) || (d == 3 && which != 2u)) { continue; }
    var o = ccSliceMake(f, sub.origin, L, ccNb(f, i, select(select(d, -1, d == 2), 2, d == 3)));
    for (var q = 0u; q < 16u; q++) {
      // Grid point (a, b) of the sub-patch: which sector holds it (0 own, 1 i + 1, 2 i − 1,
      // 3 i + 2; −1 the centre, counted with the own sector) and where, as ccSubPatchPoint finds
      // its index.
      let a = i32(q % 4u) + sub.sub.da;
      let b = i32(q / 4u) + sub.sub.db;
      var holder = 3;
      var at = 0;
      if (b < 0) { holder = 2; at = a; } else if (a >= 1) { holder = 0; at = 4 * (a - 1) + b; } else if (b >= 1) { holder = 1; at = 4 * (b - 1) - a; } else if (a == 0) { holder = -1; }
      if (holder == d || (holder == -1 && d == 0)) {
        let P = select(o[at], centre, holder == -1);
        let wx = w.x[q % 4u];
        let wy = w.y[q / 4u];
        e.p += (wy * wx) * P;
        e.pu += (wy * w.dx[q % 4u]) * P;
        e.pv += (w.dy[q / 4u] * wx) * P;
      }
    }
  }
  return e;
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
  let rot = ccRegionWord_rot(w0);
  let regular = ccRegionWord_kind(w0) == 1u;

  // PATCH: the region's frame is rot(x, y); a single-crease patch's row weights in x.
  var px = ccRot(rot, x, y);
  var mask = ccRegionWord_mask(w0);
  var src = CCRegionEval(regular, params.ccPatchIdx + w1, CCSubPatch(0u, 0u, 0u, 0u, 0u, 0, 0), vec3<f32>(0.0));
  var sc = 1.0; // tangents along the region's (x, y) per tangent along the patch's own
  // SECTOR (w1 = its fan): after L = ceil(log2(1/max(a,b))) steps the point lies on one of the
  // regular sub-patches A, B, C of the fan's slice at step L; inside the last square a radial
  // blend from the vertex's limit to the exact ring point on the ray.
  var blend = 1.0;
  var atVertex = false;
  var lb = 0u; // the fan's limit point, then its tangents at lt
  var lt = 0u;
  var derived = false; // an odd fan's even step: its sub-patch's points made again, not read
  var dFan: CCFan;
  var dL = 0u;
  var dSec = 0u;
  var dWhich = 0u;
  // A semi-sharp axis of the fan still sharp at the sub-patch's step (its σ − L > 0): sub-patch
  // A's bottom row lies on axis sec, C's left column on axis sec + 1, and each is then a
  // single-crease patch (the crease basis across that axis; the fan's eligibility makes the rest
  // of its points regular, src/gpu/cc/fans.ts).
  var creaseX = 0.0;
  var creaseY = 0.0;
  if (!regular) {
    let fan = w1;
    let sec = ccRegionWord_sector(w0);
    let off = ccRegionWord_offset(w0);
    let ab = px * exp2(-f32(off));
    let fw = ccFanWord(fan, 0u);
    let f = ccFan(fan);
    let D = f.D;
    lb = ccFanWord(fan, 5u);
    // The limit tangents of this face's sector: the fan's own at a smooth centre, else face
    // sec's (build.ts "fan limits": a sharp crease or corner has a tangent plane per sector).
    lt = select(lb + 1u, lb + 3u + 2u * sec, ccFanWord_rule(fw) != 0u);
    let m = max(ab.x, ab.y);
    // Step L: the first with max(a, b)·2^L ≥ 1, at most D: for m in [2^(e−1), 2^e), 1 − e
    // (frexp's exponent e; exact, as the powers of two are).
    let L = select(u32(clamp(1 - frexp(m).exp, 1, i32(D))), D, m <= 0.0);
    var a = ab.x * exp2(f32(L));
    var b = ab.y * exp2(f32(L));
    let t = max(a, b);
    // The vertex itself: its limit tangents stand in for the parametric ones (which vanish or
    // blow up there), the CPU reference's convention (src/subdiv/displace.ts).
    atVertex = t <= 0.0;
    if (t < 1.0) {
      blend = pow(t, bitcast<f32>(ccFanWord(fan, 4u)));
      let tt = max(t, 1e-30);
      if (a >= b) { b = b / tt; a = 1.0; } else { a = a / tt; b = 1.0; }
    }
    // Which sub-patch holds (a, b): A, B or C.
    var which = 2u;
    px = vec2<f32>(a, b - 1.0);
    if (a >= 1.0) {
      px.x = a - 1.0;
      if (b < 1.0) { which = 0u; px.y = b; } else { which = 1u; }
    }
    // The axis beside the sub-patch (A's bottom: axis sec; C's left: axis sec + 1; B has none),
    // its sharpness at step L: infinitely sharp, phantom points there; semi-sharp and still
    // sharp, the crease basis across it.
    mask = 0u;
    if (which != 1u) {
      let s = ccAxisSharp(f, select(sec, ccNb(f, sec, 1), which == 2u), L);
      if (CC_PHANTOMS && s >= AXIS_INFINITE) { mask = select(1u, 8u, which == 2u); }
      if (CC_CREASE_PATCHES && s > 0.0 && s < AXIS_INFINITE) {
        if (which == 0u) { creaseY = s; } else { creaseX = s; }
      }
    }
    src.sub = ccSubPatchOf(f, sec, L, which);
    src.origin = ccP(ccFanWord(fan, 1u));
    // An odd fan's even step is not stored: its sub-patch is summed below from points made
    // again (ccDerivedSum).
    derived = CC_ODD_SLICES && !ccSliceStored(f, L);
    if (derived) { dFan = f; dL = L; dSec = sec; dWhich = which; }
    // The sub-patch's tangents along (a, b) are 2^L times its own, and (a, b) = rot(x, y)·2^(L − off).
    sc = exp2(f32(L) - f32(off));
  }

  var bx = ccBasis(px.x);
  if (CC_CREASE_PATCHES && regular && ccRegionWord_crease(w0) == 1u) {
    // A single-crease patch: one semi-sharp crease σ on the frame's x = 0 side, σ's f32 bits
    // after the indices (Nießner, Loop, Greiner 2012): the closed-form crease row weights in x
    // times the cubic B-spline in y (wgsl/cc/crease-basis.wgsl).
    let cw = creaseRowWeights(bitcast<f32>(staticBuf[src.base + 16u]), px.x);
    bx = array<vec4<f32>, 2>(cw.value, cw.du);
  }
  var by = ccBasis(px.y);
  if (CC_CREASE_PATCHES && creaseX > 0.0) {
    let cw = creaseRowWeights(creaseX, px.x);
    bx = array<vec4<f32>, 2>(cw.value, cw.du);
  }
  if (CC_CREASE_PATCHES && creaseY > 0.0) {
    let cw = creaseRowWeights(creaseY, px.y);
    by = array<vec4<f32>, 2>(cw.value, cw.du);
  }
  let w = ccWeights(bx, by, mask);
  // Summed relative to the patch's corner (0,0), point 5: f32 precision of small patches (a
  // sub-patch made again: relative to its fan's anchor, as its points are).
  var e = CCSum(vec3<f32>(0.0), vec3<f32>(0.0), vec3<f32>(0.0));
  var o = vec3<f32>(0.0);
  if (derived) {
    e = ccDerivedSum(dFan, src, dL, dSec, dWhich, w);
  } else {
    o = ccP(ccRegionRow(src, 4u).y);
    // Row by row: a row's four points weighted in x (value and d/dx), then the row's weight in y
    // (value and d/dy). Every weight is read at a constant lane (the y weights rotate a lane per
    // row): an index into a vector that varies per iteration is slow on some compilers.
    var wy = w.y;
    var wdy = w.dy;
    for (var r = 0u; r < 16u; r += 4u) {
      let idx = ccRegionRow(src, r);
      let P0 = ccP(idx.x) - o;
      let P1 = ccP(idx.y) - o;
      let P2 = ccP(idx.z) - o;
      let P3 = ccP(idx.w) - o;
      let row = w.x.x * P0 + w.x.y * P1 + w.x.z * P2 + w.x.w * P3;
      let rowDx = w.dx.x * P0 + w.dx.y * P1 + w.dx.z * P2 + w.dx.w * P3;
      e.p += wy.x * row;
      e.pu += wy.x * rowDx;
      e.pv += wdy.x * row;
      wy = wy.yzwx;
      wdy = wdy.yzwx;
    }
  }
  // Tangents along the region's (x, y), then the face's (fs per region side). Inside a fan's
  // last square the blend's tangents are taken as the ring point's (the radial blend has no
  // useful parametric derivative at that scale).
  let tg = ccRotTangents(rot, e.pu, e.pv);
  let du = (sc * fs) * tg[0];
  let dv = (sc * fs) * tg[1];
  let pos = src.origin + o + e.p;
  let normal = ccNormal(e.pu, e.pv);
  if (blend >= 1.0) { return SurfacePoint(pos, normal, du, dv); }
  let p0 = ccP(lb);
  let n0 = ccNormal(ccP(lt), ccP(lt + 1u));
  if (atVertex) { return SurfacePoint(p0, n0, fs * ccP(lt), fs * ccP(lt + 1u)); }
  return SurfacePoint(p0 + blend * (pos - p0), normalize(mix(n0, normal, blend)), du, dv);
}

// Corner k of the regular n-gon whose table starts at `poly` (computed on the CPU in f64).
fn ccCorner(poly: u32, n: u32, k: u32) -> vec2<f32> {
  let o = params.ccPoly + 2u * (poly + k % n);
  return vec2<f32>(bitcast<f32>(staticBuf[o]), bitcast<f32>(staticBuf[o + 1u]));
}

// Sub-face k of an n-gon and (s,t): the kite round corner k of the regular n-gon, inverted by
// Newton (the map is bilinear and the kites are convex). Also (∂s/∂w_i, ∂t/∂w_i) for the
// tangents: J⁻¹ (corner − corner 0) with J the kite map's Jacobian at the solution. The
// triangle's corner 0 is the n-gon's corner 0, or its centre (the origin) when `centred`.
struct CCNgonParam { kst: vec3<f32>, d1: vec2<f32>, d2: vec2<f32> }

fn ccNgonParam(poly: u32, n: u32, fan: u32, centred: bool, w: vec3<f32>) -> CCNgonParam {
  let c0 = select(ccCorner(poly, n, 0u), vec2<f32>(0.0), centred);
  let q1 = ccCorner(poly, n, fan) - c0;
  let q2 = ccCorner(poly, n, fan + 1u) - c0;
  let p = w.x * c0 + w.y * ccCorner(poly, n, fan) + w.z * ccCorner(poly, n, fan + 1u);
  if (length(p) < 1e-6) { return CCNgonParam(vec3<f32>(0.0, 1.0, 1.0), vec2<f32>(0.0), vec2<f32>(0.0)); }
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
  let ds = (1.0 - t) * (B - A) + t * (C - D);
  let dt = (1.0 - s) * (D - A) + s * (C - B);
  let det = ds.x * dt.y - ds.y * dt.x;
  var d1 = vec2<f32>(0.0);
  var d2 = vec2<f32>(0.0);
  if (det != 0.0) {
    d1 = vec2<f32>(q1.x * dt.y - q1.y * dt.x, ds.x * q1.y - ds.y * q1.x) / det;
    d2 = vec2<f32>(q2.x * dt.y - q2.y * dt.x, ds.x * q2.y - ds.y * q2.x) / det;
  }
  return CCNgonParam(vec3<f32>(f32(k), clamp(s, 0.0, 1.0), clamp(t, 0.0, 1.0)), d1, d2);
}

// The exact limit at the cage triangle's point: what evalSurface shows before the flat-baseline
// blend, and what the factor rule looks at inside the triangle (wgsl/tess/factor-bulge.wgsl).
fn unblendedSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint {
  let w = vec3<f32>(wFixed) / 65536.0;
  let first = staticBuf[params.ccTri + 3u * t];
  let info = staticBuf[params.ccTri + 3u * t + 1u];
  let n = ccTriWord_corners(info);
  let fan = ccTriWord_fan(info);
  let centred = ccTriWord_centred(info) == 1u;
  let dd = ccTriWord_depth(info);
  // The face parameter (sub-face k, x, y), then one call of the region evaluator (a single
  // call site keeps the inlined shader small).
  // (x, y)'s derivatives along w1 and w2 carry the region's tangents to the triangle's.
  var kxy: vec3<f32>;
  var d1: vec2<f32>;
  var d2: vec2<f32>;
  if (!CC_NGONS || n == 4u) {
    let first = fan == 1u;
    kxy = select(vec3<f32>(0.0, w.y, w.y + w.z), vec3<f32>(0.0, w.y + w.z, w.z), first);
    d1 = select(vec2<f32>(1.0, 1.0), vec2<f32>(1.0, 0.0), first);
    d2 = select(vec2<f32>(0.0, 1.0), vec2<f32>(1.0, 1.0), first);
  } else {
    let np = ccNgonParam(staticBuf[params.ccTri + 3u * t + 2u], n, fan, centred, w);
    kxy = np.kst;
    d1 = np.d1;
    d2 = np.d2;
  }
  var sp = ccEvalRegion(first, dd, u32(kxy.x), kxy.y, kxy.z);
  let px = sp.du;
  sp.du = d1.x * px + d1.y * sp.dv;
  sp.dv = d2.x * px + d2.y * sp.dv;
  return sp;
}

fn evalSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint {
  let sp = unblendedSurface(t, wFixed);
  if (!FLAT_BASELINE) { return sp; }
  let w = vec3<f32>(wFixed) / 65536.0;
  // Flat baseline: the triangle of the corners' limit positions, blended to the surface by a
  // tess factor interpolated from the three edges (on an edge: that edge's factor, so both
  // triangles of the edge agree; at the corners flat and surface coincide).
  let e01 = w.x * w.y;
  let e12 = w.y * w.z;
  let e20 = w.z * w.x;
  let sum = e01 + e12 + e20;
  var F = 4.0;
  if (sum > 0.0) {
    F = (e01 * f32(edgeF(triEdge(t, 0u))) + e12 * f32(edgeF(triEdge(t, 1u))) + e20 * f32(edgeF(triEdge(t, 2u)))) / (65536.0 * sum);
  }
  // From F = 4 the blend weight k below is 1 whatever the distance term: the surface itself,
  // and the flat triangle is not read (most vertices of a close or fixed-factor view).
  if (F >= 4.0) { return sp; }
  let v0 = triVert(t, 0u);
  let v1 = triVert(t, 1u);
  let v2 = triVert(t, 2u);
  let flat = w.x * factorPos(v0) + w.y * factorPos(v1) + w.z * factorPos(v2);
  let fn0 = w.x * factorNormal(v0) + w.y * factorNormal(v1) + w.z * factorNormal(v2);
  // The blend weight: linear in F from 0 at F = 1 to the surface at F = 4, but never leaving
  // the point more than 1/lodScale pixels from the limit surface (issue 13's smooth default):
  // the point shown is flat + k·(S − flat), (1 − k)·|S − flat| from S, so k is raised to at
  // least 1 − 1/(lodScale·s) where s is |S − flat| in pixels at the point's distance from the
  // eye. Both terms are functions of the point's cage parameter and the camera: a vertex that
  // two triangles share (the weld evaluates it once anyway) gets one k, a new vertex of the
  // pop-free pattern appears where its parent is, and k moves continuously with the camera.
  let sagPx = length(sp.pos - flat) / (max(length(sp.pos - params.eye.xyz), 1e-6) * params.pixelAngle);
  let k = max(clamp((F - 1.0) / 3.0, 0.0, 1.0), 1.0 - 1.0 / max(params.lodScale * sagPx, 1.0));
  let nm = mix(fn0, sp.normal, k);
  // Tangents: the blend's with k held (k's own derivative ignored: it is a display blend).
  let fu = factorPos(v1) - factorPos(v0);
  let fv = factorPos(v2) - factorPos(v0);
  return SurfacePoint(mix(flat, sp.pos, k), select(sp.normal, normalize(nm), length(nm) > 1e-6), mix(fu, sp.du, k), mix(fv, sp.dv, k));
}

// Its normal can turn inside an edge faster than between its ends (a hairpin of the limit
// surface): the factor rule samples it along each edge (wgsl/tess/factor-bulge.wgsl).
const SURFACE_NORMAL_TURNS: bool = true;
