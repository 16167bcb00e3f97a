// ACC patch build (Bezier, Gregory and Pm ACC): one thread per patch builds its control points from
// the current cage positions, every frame (a deforming cage re-runs only this pass). The same steps
// as the f64 yardstick src/subdiv/acc.ts (cornerInfo, then one assembly per kind); the layout of
// every buffer is written down there and in src/gpu/acc/patches.ts.
//
// Precision: every corner's ring is read relative to the corner vertex (e − v, D − v), so the
// cancellations in the tangent masks (Σ cos·e) happen on small numbers, and the valence constants
// (cos tables, λ_n, s_n) come from an f64 table rounded once (WGSL's cos can be 2^-11 off).

// Starts with the generated AccBuildParams (`bp`: the patch count and the offsets of accStatic's
// sections, ACC_STATIC), the constants, the bindings (ACC_BUILD_GROUP) and the sector word's
// getters (ACC_SECTOR_WORD): src/gpu/contract/acc.ts, assembled by contract.ts accBuildPrelude.

// TRI_FACE, the patch kinds (KIND_*) and the sector kinds (SECTOR_*) are generated from
// src/subdiv/acc.ts, which writes them (accBuildPrelude).

fn cageAt(i: u32) -> vec3<f32> { return vec3<f32>(cagePos[3u * i], cagePos[3u * i + 1u], cagePos[3u * i + 2u]); }
fn valF(n: u32, i: u32) -> f32 { return bitcast<f32>(accStatic[bp.offValData + accStatic[bp.offValOffs + n] + i]); }

// What a patch needs from one corner; vectors except v are relative to v (add v back for points).
struct Corner {
  n: u32,
  c: f32,       // cos(2π/n)
  s: f32,       // sin(2π/n)
  sn: f32,      // Gregory edge length s_n
  v: vec3<f32>, // the vertex (absolute)
  p: vec3<f32>, // limit position
  t0: vec3<f32>, t1: vec3<f32>, // Loop–Schaefer mask tangents toward e_0 (next), e_1 (previous)
  f0: vec3<f32>, m0: vec3<f32>, m1: vec3<f32>, // Loop–Schaefer interior and edge points
  rp: vec3<f32>, rm: vec3<f32>, // Gregory transversals (into the face) for the edges toward e_0, e_1
  eh0: vec3<f32>, eh1: vec3<f32>, // Pm valence-4-rule edge points toward e_0, e_1
  tp0: vec3<f32>, tp1: vec3<f32>, // Pm tangent points t^(0), t^(1)
  quadNext: bool, quadPrev: bool, // the face across the edge toward e_0 (ring face n−1) / e_1 (face 1) is a quad
  sharpNext: bool, sharpPrev: bool, // the edge toward e_0 / e_1 bounds the corner's crease/corner sector
}

struct Ring { o: u32, n: u32, rot: u32, v: vec3<f32>, mid: bool }

fn ringE(r: Ring, j: u32) -> vec3<f32> { return cageAt(accStatic[bp.offRingData + r.o + (r.rot + j) % r.n]) - r.v; }
// Diagonal of local ring face j: the opposite vertex of a quad; of a triangle its centroid (exact
// CC limit) or, for Pm, the midpoint of its other two vertices (nvmesh).
fn ringD(r: Ring, j: u32) -> vec3<f32> {
  let d = accStatic[bp.offRingData + r.o + r.n + (r.rot + j) % r.n];
  if (d != TRI_FACE) { return cageAt(d) - r.v; }
  let a = ringE(r, j);
  let b = ringE(r, j + 1u);
  if (r.mid) { return 0.5 * (a + b); }
  return (a + b) / 3.0;
}

fn secF(i: u32) -> f32 { return bitcast<f32>(accStatic[bp.offSecData + i]); }

// A crease or corner vertex seen from a face in one of its sectors (src/subdiv/acc.ts
// sectorCornerInfo): sector edge j = ring edge a + j (j = 0..k), sector face j = ring face a + j.
fn sectorCorner(vert: u32, rot: u32, mid: bool, sec: u32) -> Corner {
  let o0 = accStatic[bp.offRingOffs + vert];
  let n = (accStatic[bp.offRingOffs + vert + 1u] - o0) / 2u;
  let typ = accSectorWord_kind(sec);
  let kk = accSectorWord_k(sec);
  let a = accSectorWord_a(sec);
  let r = Ring(o0, n, a, cageAt(vert), mid);
  let base = accStatic[bp.offSecOffs + 2u * kk + select(0u, 1u, typ == SECTOR_CORNER)];
  let np = secF(base + 2u);
  var k: Corner;
  k.n = 0u;
  k.c = secF(base);
  k.s = secF(base + 1u);
  k.sn = 1.0;
  k.v = r.v;
  let i0 = (rot + n - a) % n;
  let ea = ringE(r, 0u);
  let eb = ringE(r, kk);
  var A: vec3<f32>;
  var B = vec3<f32>(0.0);
  if (typ == SECTOR_CREASE) {
    k.p = (ea + eb) / 6.0;
    A = 0.5 * (ea - eb);
    let mb = base + 5u + 2u * kk;
    for (var j = 0u; j <= kk; j++) { B += secF(mb + 1u + j) * ringE(r, j); }
    for (var j = 0u; j < kk; j++) { B += secF(mb + kk + 2u + j) * ringD(r, j); }
  } else {
    k.p = vec3<f32>(0.0);
    A = ea;
    B = eb;
  }
  k.t0 = secF(base + 3u + i0) * A + secF(base + 4u + kk + i0) * B;
  k.t1 = secF(base + 4u + i0) * A + secF(base + 5u + kk + i0) * B;
  let first = i0 == 0u;
  let last = i0 + 1u == kk;
  let e0 = ringE(r, i0);
  let e1 = ringE(r, i0 + 1u);
  let d0 = ringD(r, i0);
  k.f0 = (2.0 * (e0 + e1) + d0) / (np + 5.0);
  k.m0 = e0 / 3.0;
  k.eh0 = e0 / 3.0;
  k.rp = vec3<f32>(0.0);
  if (!first) {
    let em = ringE(r, i0 - 1u);
    let dm = ringD(r, i0 - 1u);
    k.m0 = 0.5 * ((2.0 * (em + e0) + dm) / (np + 5.0) + k.f0);
    k.eh0 = (4.0 * e0 + 2.0 * em + 2.0 * e1 + dm + d0) / 18.0;
    k.rp = (e1 - em) / 3.0 + (d0 - dm) / 6.0;
    k.quadNext = accStatic[bp.offRingData + o0 + n + (rot + n - 1u) % n] != TRI_FACE;
  }
  k.m1 = e1 / 3.0;
  k.eh1 = e1 / 3.0;
  k.rm = vec3<f32>(0.0);
  if (!last) {
    let e2 = ringE(r, i0 + 2u);
    let d1 = ringD(r, i0 + 1u);
    k.m1 = 0.5 * (k.f0 + (2.0 * (e1 + e2) + d1) / (np + 5.0));
    k.eh1 = (4.0 * e1 + 2.0 * e0 + 2.0 * e2 + d0 + d1) / 18.0;
    k.rm = (e0 - e2) / 3.0 + (d0 - d1) / 6.0;
    k.quadPrev = accStatic[bp.offRingData + o0 + n + (rot + 1u) % n] != TRI_FACE;
  }
  k.tp0 = k.p + k.t0 / 3.0;
  k.tp1 = k.p + k.t1 / 3.0;
  k.sharpNext = first;
  k.sharpPrev = last;
  return k;
}

fn cornerInfo(vert: u32, rot: u32, mid: bool, sec: u32) -> Corner {
  let typ = accSectorWord_kind(sec);
  if (typ == SECTOR_CREASE || typ == SECTOR_CORNER) { return sectorCorner(vert, rot, mid, sec); }
  let o0 = accStatic[bp.offRingOffs + vert];
  let n = (accStatic[bp.offRingOffs + vert + 1u] - o0) / 2u;
  let r = Ring(o0, n, rot, cageAt(vert), mid);
  let nf = f32(n);
  var k: Corner;
  k.n = n;
  k.c = valF(n, 0u);
  k.s = valF(n, 1u);
  let lambda = valF(n, 2u);
  k.sn = valF(n, 3u);
  k.v = r.v;
  var se = vec3<f32>(0.0);
  var sd = vec3<f32>(0.0);
  var t0 = vec3<f32>(0.0);
  var t1 = vec3<f32>(0.0);
  var sc0 = vec3<f32>(0.0);
  var sc1 = vec3<f32>(0.0);
  for (var i = 0u; i < n; i++) {
    let e = ringE(r, i);
    let d = ringD(r, i);
    se += e;
    sd += d;
    let m0 = i;               // (i − 0) mod n
    let m1 = (i + n - 1u) % n; // (i − 1) mod n
    t0 += valF(n, 4u + m0) * e + valF(n, 4u + n + m0) * d;
    t1 += valF(n, 4u + m1) * e + valF(n, 4u + n + m1) * d;
    // ê_i and the Pm cosine sums Σ cos(2π(j − i)/n) ê_i, j = 0, 1.
    let eh = (4.0 * e + 2.0 * ringE(r, i + n - 1u) + 2.0 * ringE(r, i + 1u) + ringD(r, i + n - 1u) + d) / 18.0;
    if (i == 0u) { k.eh0 = eh; }
    if (i == 1u) { k.eh1 = eh; }
    sc0 += valF(n, 4u + 2u * n + (n - i) % n) * eh;
    sc1 += valF(n, 4u + 2u * n + (n + 1u - i) % n) * eh;
  }
  k.p = (4.0 * se + sd) / (nf * (nf + 5.0));
  if (typ == SECTOR_CONE) { k.p = vec3<f32>(0.0); } // a cone point stays at v
  k.t0 = t0;
  k.t1 = t1;
  let e0 = ringE(r, 0u);
  let e1 = ringE(r, 1u);
  let e2 = ringE(r, 2u);
  let en = ringE(r, n - 1u);
  let d0 = ringD(r, 0u);
  let d1 = ringD(r, 1u);
  let dn = ringD(r, n - 1u);
  k.f0 = (2.0 * (e0 + e1) + d0) / (nf + 5.0);
  let fm = (2.0 * (en + e0) + dn) / (nf + 5.0);
  let f1 = (2.0 * (e1 + e2) + d1) / (nf + 5.0);
  k.m0 = 0.5 * (fm + k.f0);
  k.m1 = 0.5 * (k.f0 + f1);
  k.rp = (e1 - en) / 3.0 + (d0 - dn) / 6.0;
  k.rm = (e0 - e2) / 3.0 + (d0 - d1) / 6.0;
  k.quadNext = accStatic[bp.offRingData + r.o + n + (rot + n - 1u) % n] != TRI_FACE;
  k.quadPrev = accStatic[bp.offRingData + r.o + n + (rot + 1u) % n] != TRI_FACE;
  k.tp0 = k.p + sc0 / (nf * lambda);
  k.tp1 = k.p + sc1 / (nf * lambda);
  return k;
}

var<private> C: array<Corner, 4>;
var<private> outBase: u32;

fn put(i: u32, p: vec3<f32>) { accPointsB[outBase + i] = vec4<f32>(p, 1.0); }

// Geometry patch b_ij at i + 4j: Loop–Schaefer points (the B-spline for a regular quad).
// Quad corner k at grid QC[k], with unit steps toward its next (QN) and previous (QP) corner.
fn gridIndex(x: i32, y: i32) -> u32 { return u32(x + 4 * y); }
fn geometryPatch() {
  var QC = array<vec2<i32>, 4>(vec2<i32>(0, 0), vec2<i32>(3, 0), vec2<i32>(3, 3), vec2<i32>(0, 3));
  var QN = array<vec2<i32>, 4>(vec2<i32>(1, 0), vec2<i32>(0, 1), vec2<i32>(-1, 0), vec2<i32>(0, -1));
  var QP = array<vec2<i32>, 4>(vec2<i32>(0, 1), vec2<i32>(-1, 0), vec2<i32>(0, -1), vec2<i32>(1, 0));
  for (var k = 0u; k < 4u; k++) {
    let c = QC[k];
    let v = C[k].v;
    put(gridIndex(c.x, c.y), v + C[k].p);
    put(gridIndex(c.x + QN[k].x, c.y + QN[k].y), v + C[k].m0);
    put(gridIndex(c.x + QP[k].x, c.y + QP[k].y), v + C[k].m1);
    put(gridIndex(c.x + QN[k].x + QP[k].x, c.y + QN[k].y + QP[k].y), v + C[k].f0);
  }
}

fn bAt(k: u32, which: u32) -> vec3<f32> {
  // which: 0 corner, 1 toward next, 2 toward previous, 3 interior.
  if (which == 0u) { return C[k].v + C[k].p; }
  if (which == 1u) { return C[k].v + C[k].m0; }
  if (which == 2u) { return C[k].v + C[k].m1; }
  return C[k].v + C[k].f0;
}

// Tangent-patch cross row along an edge A → B (Loop & Schaefer 2008).
fn crossRow(cA: f32, cB: f32, a0: vec3<f32>, a2: vec3<f32>, h1: vec3<f32>, h2: vec3<f32>, g1: vec3<f32>, g2: vec3<f32>) -> array<vec3<f32>, 2> {
  let a1 = 3.0 * (h2 - h1);
  return array<vec3<f32>, 2>(
    3.0 * (g1 - h1) + (2.0 * cA * a1 - cB * a0) / 3.0,
    3.0 * (g2 - h2) + (cA * a2 - 2.0 * cB * a1) / 3.0);
}

fn bezierPatch() {
  geometryPatch();
  // Corner derivative table (Loop & Schaefer 2008): U_{0,0}, U_{2,0}, U_{2,3}, U_{0,3}; V_{0,0}, V_{3,0}, V_{3,2}, V_{0,2}.
  put(16u, C[0].t0); put(20u, -C[1].t1); put(23u, -C[2].t0); put(19u, C[3].t1);
  put(24u, C[0].t1); put(27u, C[1].t0); put(31u, -C[2].t1); put(28u, -C[3].t0);
  // b01 = corner 0 toward previous, b02 = corner 3 toward next, b11 = f(0), b12 = f(3), …
  var x = crossRow(C[0].c, C[3].c, C[0].t1, -C[3].t0, bAt(0u, 2u), bAt(3u, 1u), bAt(0u, 3u), bAt(3u, 3u)); // u = 0
  put(17u, x[0]); put(18u, x[1]);
  x = crossRow(C[1].c, C[2].c, C[1].t0, -C[2].t1, bAt(1u, 1u), bAt(2u, 2u), bAt(1u, 3u), bAt(2u, 3u)); // u = 1
  put(21u, -x[0]); put(22u, -x[1]);
  x = crossRow(C[0].c, C[1].c, C[0].t0, -C[1].t1, bAt(0u, 1u), bAt(1u, 2u), bAt(0u, 3u), bAt(1u, 3u)); // v = 0
  put(25u, x[0]); put(26u, x[1]);
  x = crossRow(C[3].c, C[2].c, C[3].t1, -C[2].t0, bAt(3u, 2u), bAt(2u, 1u), bAt(3u, 3u), bAt(2u, 3u)); // v = 1
  put(29u, -x[0]); put(30u, -x[1]);
}

// Gregory quad (m = 4, denominator 3) or triangle (m = 3, denominator 4): P, E⁺, E⁻, F⁺, F⁻ per corner.
fn gregoryPatch(m: u32) {
  let den = select(4.0, 3.0, m == 4u);
  for (var k = 0u; k < m; k++) {
    let kn = (k + 1u) % m;
    let kp = (k + m - 1u) % m;
    let P = C[k].v + C[k].p;
    let Ep = P + C[k].t0 * (C[k].sn / 3.0);
    let Em = P + C[k].t1 * (C[k].sn / 3.0);
    let Pn = C[kn].v + C[kn].p;
    let Pp = C[kp].v + C[kp].p;
    let EnM = Pn + C[kn].t1 * (C[kn].sn / 3.0); // E_{k+1}⁻
    let EpP = Pp + C[kp].t0 * (C[kp].sn / 3.0); // E_{k−1}⁺
    let ck = C[k].c;
    // Written relative to P (the weights sum to den) for precision.
    var Fp = P + ((den - 2.0 * ck - C[kn].c) * (Ep - P) + 2.0 * ck * (EnM - P) + C[k].rp) / den;
    var Fm = P + ((den - 2.0 * ck - C[kp].c) * (Em - P) + 2.0 * ck * (EpP - P) + C[k].rm) / den;
    // A sharp edge of a quad: the Loop–Schaefer interior point (src/subdiv/acc.ts gregoryPatch).
    if (m == 4u && C[k].sharpNext) { Fp = C[k].v + C[k].f0; }
    if (m == 4u && C[k].sharpPrev) { Fm = C[k].v + C[k].f0; }
    put(5u * k, P); put(5u * k + 1u, Ep); put(5u * k + 2u, Em); put(5u * k + 3u, Fp); put(5u * k + 4u, Fm);
  }
}

// Pm patch (Myles, Ni, Peters 2008): quad c-patch (m = 4) or triangle (m = 3); ls: Loop–Schaefer boundary.
fn pmPatch(m: u32, ls: bool) {
  let mu = select(1.5, 1.0, m == 4u);
  var cc: array<vec3<f32>, 4>;
  var tp: array<vec3<f32>, 4>;
  var tm: array<vec3<f32>, 4>;
  var phi: array<vec3<f32>, 4>;
  var eh0: array<vec3<f32>, 4>;
  var eh1: array<vec3<f32>, 4>;
  for (var k = 0u; k < m; k++) {
    cc[k] = C[k].v + C[k].p;
    // Bezier-ACC triangles: Loop–Schaefer edge points on edges shared with a quad (the quad's
    // boundary curve), Pm tangent points on triangle–triangle edges.
    tp[k] = C[k].v + select(C[k].tp0, C[k].m0, ls && C[k].quadNext);
    tm[k] = C[k].v + select(C[k].tp1, C[k].m1, ls && C[k].quadPrev);
    eh0[k] = C[k].v + C[k].eh0;
    eh1[k] = C[k].v + C[k].eh1;
  }
  // Face points from the cage face, relative to corner k.
  for (var k = 0u; k < m; k++) {
    let a = C[(k + 1u) % m].v - C[k].v;
    let b = C[(k + m - 1u) % m].v - C[k].v;
    if (m == 4u) {
      phi[k] = C[k].v + (2.0 * a + 2.0 * b + (C[(k + 2u) % 4u].v - C[k].v)) / 9.0;
    } else {
      phi[k] = C[k].v + 2.5 * (a + b) / 9.0;
    }
  }
  var b211: array<vec3<f32>, 4>;
  var b121: array<vec3<f32>, 4>;
  for (var k = 0u; k < m; k++) {
    let k1 = (k + 1u) % m;
    let U0 = tp[k] - cc[k];
    let U1 = tm[k1] - tp[k];
    let U2 = cc[k1] - tm[k1];
    let S = 4.0 * mu * (C[k].s + C[k1].s);
    b211[k] = cc[k] + 0.75 * U0 + (1.0 + C[k].c) / (4.0 * mu) * U1 + (2.0 * mu - 1.0 - C[k1].c) / (8.0 * mu) * U0 + 3.0 * (phi[k] - eh0[k]) / S;
    b121[k] = cc[k1] - 0.75 * U2 - (1.0 + C[k1].c) / (4.0 * mu) * U1 - (2.0 * mu - 1.0 - C[k].c) / (8.0 * mu) * U2 + 3.0 * (phi[k1] - eh1[k1]) / S;
  }
  // Centre, relative to corner 0 (weights sum to 64 or 51).
  let o = cc[0];
  var centre = vec3<f32>(0.0);
  for (var k = 0u; k < m; k++) {
    let k1 = (k + 1u) % m;
    centre += select(2.0, 1.0, m == 4u) * (cc[k] - o) + 9.0 * (phi[k] - o) + 3.0 * (eh0[k] - o) + 3.0 * (eh1[k1] - o);
  }
  centre = o + centre / select(51.0, 64.0, m == 4u);
  for (var k = 0u; k < m; k++) {
    var b112: vec3<f32>;
    if (m == 4u) {
      var w = array<f32, 4>(3.0, 1.0, -1.0, -3.0);
      var s = vec3<f32>(0.0);
      for (var j = 0u; j < 4u; j++) { s += w[j] * (b211[(k + j) % 4u] - b121[(k + j + 1u) % 4u]); }
      b112 = centre + s / 16.0;
    } else {
      // (3/2)C − c_o/12 − (t_o⁺ + t_o⁻)/24 − (b211_o + b121_{k+1})/6, o = k + 2, relative to C.
      let q = (k + 2u) % 3u;
      b112 = centre - (cc[q] - centre) / 12.0 - ((tp[q] - centre) + (tm[q] - centre)) / 24.0
        - ((b211[q] - centre) + (b121[(k + 1u) % 3u] - centre)) / 6.0;
    }
    put(6u * k, cc[k]); put(6u * k + 1u, tp[k]); put(6u * k + 2u, tm[(k + 1u) % m]);
    put(6u * k + 3u, b211[k]); put(6u * k + 4u, b121[k]); put(6u * k + 5u, b112);
  }
  if (m == 3u) { put(18u, centre); }
}

@compute @workgroup_size(WORKGROUP_SIZE)
fn buildPatches(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let thread = (wid.y * GRID_X + wid.x) * WORKGROUP_SIZE + lid;
  if (thread >= bp.nPatches) { return; }
  let f = accStatic[bp.offOrder + thread];
  let kind = accPatchesB[2u * f];
  outBase = accPatchesB[2u * f + 1u];
  let tri = kind == KIND_GREGORY_TRI || kind == KIND_PM_TRI || kind == KIND_PM_TRI_LS;
  let m = select(4u, 3u, tri);
  let mid = kind == KIND_PM_QUAD || kind == KIND_PM_TRI;
  for (var k = 0u; k < m; k++) {
    let b = bp.offCorners + 8u * f + 2u * k;
    let sec = accStatic[bp.offSectors + 4u * f + k];
    C[k] = cornerInfo(accStatic[b], accStatic[b + 1u], mid, sec);
    if (kind == KIND_PM_TRI_LS) {
      // Exact corner and Loop–Schaefer points (centroid rule) but the midpoint rule's Pm edge and
      // tangent points, whose twist terms cancel across triangle–triangle edges (src/subdiv/acc.ts).
      let cm = cornerInfo(accStatic[b], accStatic[b + 1u], true, sec);
      C[k].eh0 = cm.eh0;
      C[k].eh1 = cm.eh1;
      C[k].tp0 = C[k].p + (cm.tp0 - cm.p);
      C[k].tp1 = C[k].p + (cm.tp1 - cm.p);
    }
  }
  switch (kind) {
    case 0u: { geometryPatch(); }
    case 1u: { bezierPatch(); }
    case 2u: { gregoryPatch(4u); }
    case 3u: { gregoryPatch(3u); }
    case 4u: { pmPatch(4u, false); }
    case 5u: { pmPatch(3u, false); }
    default: { pmPatch(3u, true); }
  }
}
