// Catmull-Clark patch build ("subdivision"), run whenever the cage moves: every point the
// evaluator reads, made from the current cage positions by the topology-only data of
// src/gpu/cc/build.ts (its header has the layouts). Its declarations are generated (below). Points are f32 xyz: the cage positions (index < ccCageVerts)
// then, from params.offCtrl in cageBuf, the refined levels, the fans' slices and limits.
//   points   one thread per point of one level (one dispatch a level), its rule from its word;
//            an edge or vertex point computes the new face points it reads itself (levelInp),
//            by the same code as the face point's own thread, so a level needs no second dispatch
//   slices   the EV slice kernel: one thread per sector, several fans per workgroup, the fan's
//            2-ring ping-ponged in workgroup memory, one Catmull-Clark step per iteration
//   limits   one thread per fan: limit position and tangents of its centre (Halstead, Kass, DeRose
//            1993); then one per prepared vertex: its fan's limit where the factor rule reads it

// Declared by the generated prelude (src/gpu/contract/contract.ts ccBuildPrelude): Params, the constants
// (WORKGROUP_SIZE, GRID_X, CC_NONE), `range` and the bindings params, staticBuf, cageBuf; then
// the packed words' getters (src/gpu/cc/words.ts); then wgsl/cc/slices.wgsl, which the evaluator
// shares: ccP (a point), ccFan and ccNb (a fan's slices and sectors), sliceStep, ccSliceMake.

fn ptAt(p: u32) -> u32 { return select(params.offCtrl + 3u * (p - params.ccCageVerts), 3u * p, p < params.ccCageVerts); }
fn setPt(p: u32, v: vec3<f32>) {
  let o = ptAt(p);
  cageBuf[o] = v.x;
  cageBuf[o + 1u] = v.y;
  cageBuf[o + 2u] = v.z;
}
fn inp(i: u32) -> vec3<f32> { return ccP(staticBuf[params.ccInputs + i]); }

// Face point p (its rule's corners are points of the level before): the centroid.
fn facePoint(p: u32) -> vec3<f32> {
  let r = params.ccRules + 2u * (p - params.ccCageVerts);
  let n = ccRuleWord_count(staticBuf[r]);
  let first = staticBuf[r + 1u];
  var s = vec3<f32>(0.0);
  for (var j = 0u; j < n; j++) { s += inp(first + j); }
  return s / f32(n);
}

// Input i of an edge or vertex point of this level: a point of the level before, or one of this
// level's new face points, computed here as its own thread computes it (bit for bit the value it
// stores), so that the level's points are one dispatch.
fn levelInp(i: u32) -> vec3<f32> {
  let p = staticBuf[params.ccInputs + i];
  if (p >= range.faceFirst && p < range.first + range.count) { return facePoint(p); }
  return ccP(p);
}

// Vertex masks (OpenSubdiv's Catmull-Clark vertex rules) over the inputs [v, e_0..e_{m-1}, F_0..F_{k-1}].
fn vertexMask(rule: u32, first: u32, m: u32, k: u32, ia: u32, ib: u32) -> vec3<f32> {
  let v = levelInp(first);
  if (rule == 2u) { return v; }
  if (rule == 1u) { return 0.75 * v + 0.125 * (levelInp(first + 1u + ia) + levelInp(first + 1u + ib)); }
  var s = vec3<f32>(0.0);
  for (var i = 0u; i < m + k; i++) { s += levelInp(first + 1u + i); }
  let n = f32(m);
  return ((n - 2.0) / n) * v + s / (n * n);
}

@compute @workgroup_size(WORKGROUP_SIZE)
fn points(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let i = (wid.y * GRID_X + wid.x) * WORKGROUP_SIZE + lid;
  if (i >= range.count) { return; }
  let p = range.first + i;
  let r = params.ccRules + 2u * (p - params.ccCageVerts);
  let w0 = staticBuf[r];
  let first = staticBuf[r + 1u];
  let kind = ccRuleWord_kind(w0);
  var out: vec3<f32>;
  if (kind == 0u) {
    out = facePoint(p);
  } else if (kind == 1u) {
    // Edge point: crease (s ≥ 1, boundary), smooth, or their blend for 0 < s < 1.
    let n = ccRuleWord_count(w0);
    let sh = select(0.0, bitcast<f32>(staticBuf[params.ccInputs + first + 4u]), ccRuleWord_sharp(w0) == 1u);
    let mid = 0.5 * (levelInp(first) + levelInp(first + 1u));
    if (n == 2u || sh >= 1.0) {
      out = mid;
    } else {
      let sm = 0.25 * (levelInp(first) + levelInp(first + 1u) + levelInp(first + 2u) + levelInp(first + 3u));
      out = select(sm, sh * mid + (1.0 - sh) * sm, sh > 0.0);
    }
  } else {
    // Vertex point: parent rule, child rule and OpenSubdiv's transitional weight W (a sharp
    // vertex's crease pair and W follow its inputs).
    let pr = ccRuleWord_parent(w0);
    let cr = ccRuleWord_child(w0);
    let m = ccRuleWord_count(w0);
    let k = ccRuleWord_faces(w0);
    var ia = 0u;
    var ib = 0u;
    var W = 1.0;
    if ((pr | cr) != 0u) {
      let x = params.ccInputs + first + 1u + m + k;
      ia = ccPairWord_a(staticBuf[x]);
      ib = ccPairWord_b(staticBuf[x]);
      W = bitcast<f32>(staticBuf[x + 1u]);
    }
    out = vertexMask(pr, first, m, k, ia, ib);
    if (cr != pr) { out = W * out + (1.0 - W) * vertexMask(cr, first, m, k, ia, ib); }
  }
  setPt(p, out);
}

// ---------------------------------------------------------------------------------------------
// The EV slice kernel (src/gpu/cc/build.ts, "2. Fans"). Sector i of a fan owns the points (a, b), a ∈ {1,2},
// b ∈ {0,1,2} of its frame (a along axis i, b along axis i+1); (0, b) belongs to sector i+1,
// (a, −1) to sector i−1, (0, 0) is the centre. Per step: face points → barrier → edge and
// vertex points (they read only old points and the new face points, so one stage) and the
// centre (the fan's first thread sums over the fan) → barrier → the new 6 points and centre
// replace the old → barrier. All points are offsets from the fan's anchor (its centre at the
// start level): subdivision is affine, and deep levels keep f32's relative precision.
// Inside the slices every point but the centre and the axis points is a smooth valence-4
// vertex, an edge point of an edge made inside a face, or a face point (the eligibility test
// of build.ts), so the regular masks below are exact; the axis points use the crease rules
// by the axis's sharpness (infinitely sharp: boundaries, creases into the EV, darts; semi-sharp:
// decaying one unit a step, wgsl/cc/slices.wgsl sliceStep), the centre its rule of the step.

var<workgroup> P: array<vec3<f32>, 6u * WORKGROUP_SIZE>;   // 6 per thread: (1,0) (2,0) (1,1) (2,1) (1,2) (2,2)
var<workgroup> C: array<vec3<f32>, WORKGROUP_SIZE>;    // the centre, at the fan's first thread
var<workgroup> wideFanOf: u32;                          // the workgroup's wide fan, or CC_NONE

// A fan's words unpacked (src/gpu/cc/build.ts "fans"): sectors, valence, boundary, rule, depth D,
// its anchor point, its slices' base and its crease pair (ia, ib); f: its slices as
// wgsl/cc/slices.wgsl reads them.
struct FanHead { ns: u32, n: u32, boundary: bool, rule: u32, D: u32, anchor: vec3<f32>, sliceBase: u32, ia: u32, ib: u32, f: CCFan }

fn fanHead(fan: u32) -> FanHead {
  let w0 = ccFanWord(fan, 0u);
  let pair = ccFanWord(fan, 6u);
  let f = ccFan(fan);
  return FanHead(f.ns, f.n, f.boundary, ccFanWord_rule(w0), f.D, ccP(ccFanWord(fan, 1u)), f.base, ccPairWord_a(pair), ccPairWord_b(pair), f);
}

// The centre after a step: smooth (and dart) from every sector's (1,0) and its cell-00 face
// point (p10 of sector j, p11 of sector j and p10 of sector j + 1), crease along axes ia, ib,
// or corner (it stays).
fn centreSmoothTerm(c: vec3<f32>, p10: vec3<f32>, p11: vec3<f32>, n10: vec3<f32>) -> vec3<f32> {
  return p10 + 0.25 * (c + p10 + p11 + n10);
}

// The centre's rule in step k: the fan's one rule (word 0, the crease pair in word 6), or for a
// centre with semi-sharp edges step k's entry of its table (word 8: src/gpu/cc/fans.ts
// stepRules): the rule before and after the step, the crease pair and OpenSubdiv's W, as a
// vertex point of the levels has them (`points`).
struct CentreRule { parent: u32, child: u32, ia: u32, ib: u32, W: f32 }

fn centreRule(fan: u32, rule: u32, ia: u32, ib: u32, k: u32) -> CentreRule {
  let table = ccFanWord(fan, 8u);
  if (table == CC_NONE) { return CentreRule(rule, rule, ia, ib, 1.0); }
  let o = params.ccSectors + table + 3u * (k - 1u);
  let w = staticBuf[o];
  let pair = staticBuf[o + 1u];
  return CentreRule(ccStepRuleWord_parent(w), ccStepRuleWord_child(w), ccPairWord_a(pair), ccPairWord_b(pair), bitcast<f32>(staticBuf[o + 2u]));
}

// The centre after a step by one rule, from the fan's old points in workgroup memory (its first
// thread's `first`): smooth (and dart), crease along axes ia, ib, or corner (it stays).
fn centreMask(rule: u32, c: vec3<f32>, first: u32, n: u32, ia: u32, ib: u32) -> vec3<f32> {
  if (rule == 1u) { return 0.75 * c + 0.125 * (P[6u * (first + ia)] + P[6u * (first + ib)]); }
  if (rule != 0u) { return c; }
  var s = vec3<f32>(0.0);
  for (var j = 0u; j < n; j++) { s += centreSmoothTerm(c, P[6u * (first + j)], P[6u * (first + j) + 2u], P[6u * (first + (j + 1u) % n)]); }
  let nf = f32(n);
  return ((nf - 2.0) / nf) * c + s / (nf * nf);
}

@compute @workgroup_size(WORKGROUP_SIZE)
fn slices(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let wg = wid.y * GRID_X + wid.x;
  // (Workgroups past the last one exist when the dispatch is folded into 2D.)
  let th = select(CC_NONE, staticBuf[params.ccThreads + wg * WORKGROUP_SIZE + lid], wg < params.ccSliceGroups);
  // A fan wider than a workgroup has one of its own, marked in its first word (src/gpu/cc/fans.ts
  // packThreads); the whole workgroup takes that path (a uniform branch: barriers inside).
  if (lid == 0u) {
    wideFanOf = select(CC_NONE, ccThreadWord_fan(th), th != CC_NONE && ccThreadWord_sector(th) == CC_WIDE_FAN);
  }
  let wide = workgroupUniformLoad(&wideFanOf);
  if (wide != CC_NONE) {
    wideSlices(wide, lid);
    return;
  }
  let valid = th != CC_NONE;
  var fan = 0u;
  var sec = 0u;
  var ns = 1u;
  var n = 1u;
  var boundary = false;
  var rule = 0u;
  var D = 0u;
  var anchor = vec3<f32>(0.0);
  var sliceBase = 0u;
  var fs: CCFan;
  var axisWord = 0u;
  var pseudo = false;
  var ia = 0u;
  var ib = 0u;
  if (valid) {
    fan = ccThreadWord_fan(th);
    sec = ccThreadWord_sector(th);
    let h = fanHead(fan);
    ns = h.ns;
    n = h.n;
    boundary = h.boundary;
    rule = h.rule;
    D = h.D;
    anchor = h.anchor;
    sliceBase = h.sliceBase;
    fs = h.f;
    ia = h.ia;
    ib = h.ib;
    let sb = ccFanWord(fan, 3u) + 7u * sec;
    axisWord = staticBuf[params.ccSectors + sb];
    pseudo = boundary && sec == n;
    for (var j = 0u; j < 6u; j++) { P[6u * lid + j] = ccP(staticBuf[params.ccSectors + sb + 1u + j]) - anchor; }
    if (sec == 0u) { C[lid] = vec3<f32>(0.0); }
  }
  // Neighbour threads (fans are contiguous; a boundary fan's sector 0 has no previous sector,
  // and reads itself where the crease rules of its infinitely sharp axis need nothing).
  let first = lid - sec;
  var prev = select(lid - 1u, first + n - 1u, sec == 0u);
  if (boundary && sec == 0u) { prev = lid; }
  var next = select(lid + 1u, first, !boundary && sec == n - 1u);
  if (pseudo) { next = lid; }
  workgroupBarrier();
  for (var k = 1u; k <= params.ccMaxDepth; k++) {
    let live = valid && k <= D;
    var o: array<vec3<f32>, 12>;
    let c = C[first];
    var cNew = c;
    if (live) {
      let p = array<vec3<f32>, 6>(P[6u * lid], P[6u * lid + 1u], P[6u * lid + 2u], P[6u * lid + 3u], P[6u * lid + 4u], P[6u * lid + 5u]);
      o = sliceStep(p, c, P[6u * next], P[6u * next + 1u], P[6u * prev], P[6u * prev + 2u], P[6u * prev + 4u],
                    ccAxisSharpness(axisWord, k - 1u), pseudo);
      if (sec == 0u) {
        let r = centreRule(fan, rule, ia, ib, k);
        cNew = centreMask(r.parent, c, first, n, r.ia, r.ib);
        if (r.child != r.parent) { cNew = r.W * cNew + (1.0 - r.W) * centreMask(r.child, c, first, n, r.ia, r.ib); }
      }
    }
    workgroupBarrier();
    if (live) {
      P[6u * lid] = o[0];
      P[6u * lid + 1u] = o[4];
      P[6u * lid + 2u] = o[1];
      P[6u * lid + 3u] = o[5];
      P[6u * lid + 4u] = o[2];
      P[6u * lid + 5u] = o[6];
      // Step k's slice (layout: src/gpu/cc/build.ts): the centre, and every sector's 12 points
      // (a, b), a ∈ 1..3, b ∈ 0..3, at 4(a − 1) + b: the evaluator's sub-patches A, B, C of
      // step k read them as they are (wgsl/cc/surface.wgsl ccEvalRegion), an odd fan's even
      // steps made again from the step before where they are read (ccSliceMake).
      if (sec == 0u) {
        C[lid] = cNew;
        setPt(sliceBase + k - 1u, cNew);
      }
      if (ccSliceStored(fs, k)) {
        let sb = ccSliceStepBase(fs, k) + 12u * sec;
        for (var q = 0u; q < 12u; q++) { setPt(sb + q, o[q]); }
      }
    }
    workgroupBarrier();
  }
}

// centreMask for a wide fan: the old points from its stored slice (or the start level's).
fn wideCentreMask(h: FanHead, k: u32, rule: u32, c: vec3<f32>, ia: u32, ib: u32) -> vec3<f32> {
  if (rule == 1u) { return 0.75 * c + 0.125 * (ccSliceOld(h.f, h.anchor, k, ia, 0u) + ccSliceOld(h.f, h.anchor, k, ib, 0u)); }
  if (rule != 0u) { return c; }
  var s = vec3<f32>(0.0);
  for (var j = 0u; j < h.n; j++) {
    s += centreSmoothTerm(c, ccSliceOld(h.f, h.anchor, k, j, 0u), ccSliceOld(h.f, h.anchor, k, j, 2u),
                          ccSliceOld(h.f, h.anchor, k, (j + 1u) % h.n, 0u));
  }
  let nf = f32(h.n);
  return ((nf - 2.0) / nf) * c + s / (nf * nf);
}

// A fan with more sectors than a workgroup has threads (any valence up to the fan word's field):
// the same steps, its threads taking sectors lid, lid + WORKGROUP_SIZE, …, reading the step
// before from its stored slice (global memory) instead of workgroup memory, the centre made by
// thread 0; a storage barrier between steps.
fn wideSlices(fan: u32, lid: u32) {
  let h = fanHead(fan);
  for (var k = 1u; k <= params.ccMaxDepth; k++) {
    if (k <= h.D) {
      let c = select(ccP(h.sliceBase + k - 2u), vec3<f32>(0.0), k == 1u);
      for (var sec = lid; sec < h.ns; sec += WORKGROUP_SIZE) {
        let o = ccSliceMake(h.f, h.anchor, k, sec);
        let sb = ccSliceStepBase(h.f, k) + 12u * sec;
        for (var q = 0u; q < 12u; q++) { setPt(sb + q, o[q]); }
      }
      if (lid == 0u) {
        let r = centreRule(fan, h.rule, h.ia, h.ib, k);
        var cNew = wideCentreMask(h, k, r.parent, c, r.ia, r.ib);
        if (r.child != r.parent) { cNew = r.W * cNew + (1.0 - r.W) * wideCentreMask(h, k, r.child, c, r.ia, r.ib); }
        setPt(h.sliceBase + k - 1u, cNew);
      }
    }
    storageBarrier();
  }
}

// ---------------------------------------------------------------------------------------------
// Limit position and tangents of each fan's centre (Halstead, Kass, DeRose 1993; OpenSubdiv's crease and corner
// masks) from its last level: the
// start-level ring when the fan has no slices, else its step-D ring and centre (offsets from
// the anchor; step D's slice).
// Written at the fan's limit base: P (absolute), T1, T2 (normal = T1 × T2).

fn ringPt(fan: u32, D: u32, ns: u32, anchor: vec3<f32>, i: u32, which: u32) -> vec3<f32> {
  // which: 0 → (1,0) of sector i, 1 → (1,1): the slice's points 0 and 1 of step D
  if (D == 0u) {
    return ccP(staticBuf[params.ccSectors + ccFanWord(fan, 3u) + 7u * i + 1u + 2u * which]) - anchor;
  }
  let f = ccFan(fan);
  if (ccSliceStored(f, D)) { return ccP(ccSliceStepBase(f, D) + 12u * i + which); }
  let o = ccSliceMake(f, anchor, D, i); // an odd fan's even last step
  return select(o[0], o[1], which == 1u);
}

// Tangents of the crease span of faces a..b−1 (axes a and b infinitely sharp, indices mod n):
// T1 along the crease (normal = T1 × T2 points outward for faces in ring order), T2 into the
// span: the exact mask for a span of 2 faces (the regular crease), the mean of the span's ring
// points otherwise (on the right side, a few degrees off the exact cross tangent: only the
// vertex itself, its last square's blend and the factor rule read it).
fn creaseTangents(fan: u32, D: u32, ns: u32, n: u32, anchor: vec3<f32>, P0: vec3<f32>, a: u32, b: u32) -> array<vec3<f32>, 2> {
  let T1 = 0.5 * (ringPt(fan, D, ns, anchor, ringAxis(a, n, ns), 0u) - ringPt(fan, D, ns, anchor, ringAxis(b, n, ns), 0u));
  var s = vec3<f32>(0.0);
  var w = 0.0;
  for (var i = a; i < b; i++) {
    s += ringPt(fan, D, ns, anchor, i % n, 1u);
    w += 1.0;
    if (i > a) { s += 4.0 * ringPt(fan, D, ns, anchor, i % n, 0u); w += 4.0; }
  }
  return array<vec3<f32>, 2>(T1, s / max(w, 1.0) - P0);
}

// Axis j of the ring: on a boundary the pseudo-sector n is the last axis, else j mod n.
fn ringAxis(j: u32, n: u32, ns: u32) -> u32 { return select(j % n, j, ns > n); }

// Tangents of face i's corner at a corner vertex (the vertex itself is the limit). Where both
// of the face's edges there are infinitely sharp: along them, e_i − c and e_(i+1) − c, as the CPU
// reference. Where either is not (a corner tag among smooth or decayed edges) the surface has no
// tangent plane there (the CPU reference says so) and the two edges' directions can be nearly
// parallel (a rounded corner): the face's quad of the last ring (c, e_i, d_i, e_(i+1)) by its
// diagonals instead, whose normal is the quad's own.
fn cornerTangents(fan: u32, D: u32, ns: u32, n: u32, boundary: bool, anchor: vec3<f32>, c: vec3<f32>, i: u32) -> array<vec3<f32>, 2> {
  let j = select((i + 1u) % n, i + 1u, boundary);
  let ei = ringPt(fan, D, ns, anchor, i, 0u);
  let ej = ringPt(fan, D, ns, anchor, j, 0u);
  let sb = params.ccSectors + ccFanWord(fan, 3u);
  if (staticBuf[sb + 7u * i] == CC_AXIS_INFINITE && staticBuf[sb + 7u * j] == CC_AXIS_INFINITE) { return array<vec3<f32>, 2>(ei - c, ej - c); }
  return array<vec3<f32>, 2>(ringPt(fan, D, ns, anchor, i, 1u) - c, ej - ei);
}

// A fan's centre: its limit position (anchor + P0) and tangents (T1, T2), and what the per-face
// tangents of a crease or corner fan need besides. Its one call site is `limits`, for a fan's
// own thread and for a vertex's alike, so the two agree bit for bit.
struct FanCentre { pos: vec3<f32>, P0: vec3<f32>, T1: vec3<f32>, T2: vec3<f32>, c: vec3<f32>, head: FanHead }

fn fanCentre(fan: u32) -> FanCentre {
  let h = fanHead(fan);
  let ns = h.ns;
  let n = h.n;
  let boundary = h.boundary;
  let rule = h.rule;
  let D = h.D;
  let anchor = h.anchor;
  var c = vec3<f32>(0.0);
  if (D > 0u) { c = ccP(h.sliceBase + D - 1u); }
  let ia = h.ia;
  let ib = h.ib;
  var P0 = c;
  var T1 = vec3<f32>(0.0);
  var T2 = vec3<f32>(0.0);
  if (rule == 0u && !boundary) {
    // Smooth (and dart): P = (n²c + 4Σe + Σd)/(n(n+5)); tangents with cos(iθ) from the CPU.
    let cb = params.ccCos + ccFanWord(fan, 7u);
    let inv = bitcast<f32>(staticBuf[cb + n]);
    var se = vec3<f32>(0.0);
    for (var i = 0u; i < n; i++) {
      let e = ringPt(fan, D, ns, anchor, i, 0u);
      let d = ringPt(fan, D, ns, anchor, i, 1u);
      se += 4.0 * e + d;
      let ci = bitcast<f32>(staticBuf[cb + i]);
      let ci1 = bitcast<f32>(staticBuf[cb + (i + 1u) % n]);
      let cim = bitcast<f32>(staticBuf[cb + (i + n - 1u) % n]);
      T1 += 4.0 * ci * e + (ci + ci1) * inv * d;
      T2 += 4.0 * cim * e + (cim + ci) * inv * d;
    }
    let nf = f32(n);
    P0 = (nf * nf * c + se) / (nf * (nf + 5.0));
  } else if (rule == 1u) {
    // Crease: P = ⅔c + ⅙(e_a + e_b), T1 along the crease, T2 into the span ia..ib of faces.
    P0 = (2.0 / 3.0) * c + (1.0 / 6.0) * (ringPt(fan, D, ns, anchor, ia, 0u) + ringPt(fan, D, ns, anchor, ib, 0u));
    let t = creaseTangents(fan, D, ns, n, anchor, P0, ia, ib);
    T1 = t[0];
    T2 = t[1];
  } else {
    // Corner: P = c; the tangents of face 0's corner.
    let t = cornerTangents(fan, D, ns, n, boundary, anchor, c, 0u);
    T1 = t[0];
    T2 = t[1];
  }
  return FanCentre(anchor + P0, P0, T1, T2, c, h);
}

// One dispatch: a thread per fan (its centre's limit, and per face the tangents of its own
// sector at a crease or corner), then a thread per prepared vertex (vertexLimit: the limit where
// the factor rule and the flat baseline read it, its fan's centre computed again rather than
// read back, so that no second dispatch has to wait for the fans).
@compute @workgroup_size(WORKGROUP_SIZE)
fn limits(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let i = (wid.y * GRID_X + wid.x) * WORKGROUP_SIZE + lid;
  if (i >= params.nFans + params.nVerts) { return; }
  let isFan = i < params.nFans;
  let v = i - select(params.nFans, 0u, isFan);
  var fan = i;
  if (!isFan) {
    fan = staticBuf[params.ccVertexFan + v];
    if (fan != CC_NONE && ccVertexLimitWord_crease(fan) == 1u) { fan = CC_NONE; } // its own closed form
  }
  var C: FanCentre; // zero where the vertex has no fan
  if (fan != CC_NONE) { C = fanCentre(fan); }
  if (!isFan) {
    vertexLimit(v, fan != CC_NONE, C);
    return;
  }
  let h = C.head; // the fan's words, read once (fanCentre)
  let ns = h.ns;
  let n = h.n;
  let boundary = h.boundary;
  let rule = h.rule;
  let D = h.D;
  let ia = h.ia;
  let ib = h.ib;
  let anchor = h.anchor;
  let c = C.c;
  let P0 = C.P0;
  let T1 = C.T1;
  let T2 = C.T2;
  let lb = ccFanWord(fan, 5u);
  // Each face's own sector at a crease or corner (build.ts "fan limits"): the span of faces
  // between the two sharp edges round face i, or face i alone at a corner.
  // A crease's two spans are computed once each: ia..ib is the fan's own (T1, T2 above), the
  // other (ib..ia + n) exists off a boundary only.
  if (rule != 0u) {
    let own = array<vec3<f32>, 2>(T1, T2);
    var other = own;
    if (rule == 1u && !boundary) { other = creaseTangents(fan, D, ns, n, anchor, P0, ib, ia + n); }
    for (var i = 0u; i < n; i++) {
      var t = other;
      if (rule == 2u) {
        t = cornerTangents(fan, D, ns, n, boundary, anchor, c, i);
      } else if (i >= ia && i < ib) {
        t = own;
      }
      setPt(lb + 3u + 2u * i, t[0]);
      setPt(lb + 4u + 2u * i, t[1]);
    }
  }
  setPt(lb, C.pos);
  setPt(lb + 1u, T1);
  setPt(lb + 2u, T2);
}

// A prepared vertex (the cage's, then the face centres of src/gpu/tess/prepare.ts): its limit
// position and normal, where the factor rule and the flat baseline read them; `centre` is its
// fan's when it has one (hasFan).
fn vertexLimit(v: u32, hasFan: bool, centre: FanCentre) {
  let fan = staticBuf[params.ccVertexFan + v];
  let o = params.offPositions + 3u * v;
  var p = vec3<f32>(cageBuf[o], cageBuf[o + 1u], cageBuf[o + 2u]);
  var nn = vec3<f32>(cageBuf[params.offNormals + 3u * v], cageBuf[params.offNormals + 3u * v + 1u], cageBuf[params.offNormals + 3u * v + 2u]);
  if (fan != CC_NONE && ccVertexLimitWord_crease(fan) == 1u) {
    // On a straight semi-sharp crease σ = k + f (build.ts creaseVertexGrid: 3×3 points at 3a + b,
    // a across, b along, then σ): the corner of its single-crease patches, the closed form of
    // wgsl/cc/crease-basis.wgsl at u = 0: across (ρ/6, 1 − ρ/3, ρ/6) with ρ = 2^-k (1 − f/2), along
    // the B-spline's (1/6, 2/3, 1/6); the derivatives (−½, 0, ½) both ways.
    let b = params.ccPatchIdx + ccVertexLimitWord_index(fan);
    let sigma = bitcast<f32>(staticBuf[b + 9u]);
    let k = floor(sigma);
    let rho = ldexp(1.0, -i32(k)) * (1.0 - 0.5 * (sigma - k));
    let wa = array<f32, 3>(rho / 6.0, 1.0 - rho / 3.0, rho / 6.0);
    let wb = array<f32, 3>(1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0);
    let d = array<f32, 3>(-0.5, 0.0, 0.5);
    let c = ccP(staticBuf[b + 4u]);
    var pp = vec3<f32>(0.0);
    var pa = vec3<f32>(0.0);
    var pb = vec3<f32>(0.0);
    for (var i = 0u; i < 3u; i++) {
      for (var j = 0u; j < 3u; j++) {
        let q = ccP(staticBuf[b + 3u * i + j]) - c;
        pp += wa[i] * wb[j] * q;
        pa += d[i] * wb[j] * q;
        pb += wa[i] * d[j] * q;
      }
    }
    p = c + pp;
    let nc = cross(pa, pb);
    if (length(nc) > 0.0) { nn = normalize(nc); }
  } else if (hasFan) {
    p = centre.pos;
    let nc = cross(centre.T1, centre.T2);
    if (length(nc) > 0.0) { nn = normalize(nc); }
  }
  let op = params.offFactorPos + 3u * v;
  let on = params.offFactorNormal + 3u * v;
  cageBuf[op] = p.x;
  cageBuf[op + 1u] = p.y;
  cageBuf[op + 2u] = p.z;
  cageBuf[on] = nn.x;
  cageBuf[on + 1u] = nn.y;
  cageBuf[on + 2u] = nn.z;
}
