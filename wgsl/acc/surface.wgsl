// ACC surface evaluation (Bezier, Gregory and Pm ACC), the GPU twin of src/subdiv/acc.ts
// evalPatchPoints. Self-contained except for the two buffers it reads, which the including shader
// declares (src/gpu/acc/patches.ts accBindingsWgsl writes the declarations at its binding numbers):
//
//   accPatches: array<u32>         2 per patch (= cage face): kind, first control point
//   accPoints:  array<vec4<f32>>   control points (xyz; w unused), written by wgsl/acc/build.wgsl
//
// evalAccPatch(patchId, u, v): quads at (u, v) with corners c0..c3 at (0,0), (1,0), (1,1), (0,1);
// triangles at (u, v) = (w1, w2), the barycentric weights of face corners 1 and 2. Returns the
// position and the unit shading normal (outward for counter-clockwise faces). From the
// tessellator's (triangle, weights w) on a quad split along its 0–2 diagonal (src/gpu/tess/prepare.ts):
// (c0, c1, c2) → (u, v) = (w1 + w2, w2), (c0, c2, c3) → (w1, w1 + w2) (src/gpu/tess/face-params.ts);
// on a triangle face (u, v) = (w1, w2). Kinds:
//   REGULAR       bicubic Bézier, normal = ∂u × ∂v
//   BEZIER        bicubic geometry patch; normal = T_u × T_v of the two tangent patches
//   GREGORY_QUAD  the 16-point Bézier with the rational interior blends; normal of that frozen
//                 Bézier (the blend weights' derivatives ignored, as the sample and OpenSubdiv)
//   GREGORY_TRI   quartic triangle with the three blended interior points (our G1 rule, src/subdiv/acc-evaluate.ts)
//   PM_QUAD       c-patch: one of 4 quartic sectors; PM_TRI / PM_TRI_LS: one of 3 sectors
// Quartics are evaluated by de Casteljau down to three points R; ∂P/∂(s,t,w) = 4R, and the chain
// rule through the sector's (s,t,w)(u,v) gives ∂u, ∂v, so the normal is ∂u × ∂v in every sector.

struct AccSurfacePoint {
  pos: vec3<f32>,
  normal: vec3<f32>,
  // Tangents along the patch's (u, v) whose cross product is the normal (Bezier ACC: the tangent
  // patches'), for the displacement (wgsl/tess/displace.wgsl).
  du: vec3<f32>,
  dv: vec3<f32>,
}

var<private> accQ: array<vec3<f32>, 16>;

// accPt(i) (control point i) and accPatchWord(i) (word i of the patch table) come from the
// including shader: src/gpu/acc/patches.ts accBindingsWgsl over its own buffers, or the tessellator's
// wgsl/acc/surface-tess.wgsl over its arenas.

fn accBern3(t: f32) -> vec4<f32> {
  let s = 1.0 - t;
  return vec4<f32>(s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t);
}
fn accBern3d(t: f32) -> vec4<f32> {
  let s = 1.0 - t;
  return vec4<f32>(-3.0 * s * s, 3.0 * s * s - 6.0 * s * t, 6.0 * s * t - 3.0 * t * t, 3.0 * t * t);
}
fn accBern2(t: f32) -> vec3<f32> {
  let s = 1.0 - t;
  return vec3<f32>(s * s, 2.0 * s * t, t * t);
}

// Bicubic in accQ (b_ij at i + 4j): position, ∂u, ∂v.
fn accBicubic(u: f32, v: f32) -> array<vec3<f32>, 3> {
  let bu = accBern3(u);
  let bv = accBern3(v);
  let du = accBern3d(u);
  let dv = accBern3d(v);
  var P = vec3<f32>(0.0);
  var Pu = vec3<f32>(0.0);
  var Pv = vec3<f32>(0.0);
  for (var j = 0u; j < 4u; j++) {
    var row = vec3<f32>(0.0);
    var rowd = vec3<f32>(0.0);
    for (var i = 0u; i < 4u; i++) {
      let q = accQ[i + 4u * j];
      row += bu[i] * q;
      rowd += du[i] * q;
    }
    P += bv[j] * row;
    Pu += bv[j] * rowd;
    Pv += dv[j] * row;
  }
  return array<vec3<f32>, 3>(P, Pu, Pv);
}

fn accBlend(F1: vec3<f32>, w1: f32, F2: vec3<f32>, w2: f32) -> vec3<f32> {
  let d = w1 + w2;
  if (d > 0.0) { return (w1 * F1 + w2 * F2) / d; }
  return F1;
}

// Quartic index (a, b, c), a + b + c = deg: by c, then b.
fn accQi(b: u32, c: u32, deg: u32) -> u32 { return c * (deg + 1u) - (c * (c - 1u)) / 2u + b; }

// de Casteljau in place on accQ (15 quartic coefficients) down to three points: returns
// (P, R_a, R_b, R_c); the homogeneous partials are 4·R.
fn accQuartic(a: f32, b: f32, c: f32) -> array<vec3<f32>, 4> {
  for (var deg = 4u; deg > 1u; deg--) {
    let d = deg - 1u;
    // Increasing target index: every read index is ≥ its target and > every earlier target.
    for (var cc = 0u; cc <= d; cc++) {
      for (var bb = 0u; bb + cc <= d; bb++) {
        accQ[accQi(bb, cc, d)] = a * accQ[accQi(bb, cc, deg)] + b * accQ[accQi(bb + 1u, cc, deg)] + c * accQ[accQi(bb, cc + 1u, deg)];
      }
    }
  }
  return array<vec3<f32>, 4>(a * accQ[0] + b * accQ[1] + c * accQ[2], accQ[0], accQ[1], accQ[2]);
}

fn accSetQ(a: u32, b: u32, c: u32, p: vec3<f32>) { accQ[accQi(b, c, 4u)] = p; _ = a; }

fn accGregoryQuad(o: u32, u: f32, v: f32) {
  accQ[0] = accPt(o); accQ[1] = accPt(o + 1u); accQ[4] = accPt(o + 2u);
  accQ[3] = accPt(o + 5u); accQ[2] = accPt(o + 7u); accQ[7] = accPt(o + 6u);
  accQ[15] = accPt(o + 10u); accQ[14] = accPt(o + 11u); accQ[11] = accPt(o + 12u);
  accQ[12] = accPt(o + 15u); accQ[8] = accPt(o + 16u); accQ[13] = accPt(o + 17u);
  accQ[5] = accBlend(accPt(o + 3u), u, accPt(o + 4u), v);
  accQ[6] = accBlend(accPt(o + 8u), v, accPt(o + 9u), 1.0 - u);
  accQ[10] = accBlend(accPt(o + 13u), 1.0 - u, accPt(o + 14u), 1.0 - v);
  accQ[9] = accBlend(accPt(o + 18u), 1.0 - v, accPt(o + 19u), u);
}

// Quartic slot with x on corner k, y on corner k+1, the rest on corner k+2 → (λ0, λ1, λ2) powers.
fn accTriSlot(k: u32, x: u32, y: u32, p: vec3<f32>) {
  var r = array<u32, 3>(0u, 0u, 0u);
  r[k] = x;
  r[(k + 1u) % 3u] = y;
  r[(k + 2u) % 3u] = 4u - x - y;
  accSetQ(r[0], r[1], r[2], p);
}

fn accGregoryTri(o: u32, l: vec3<f32>) {
  for (var k = 0u; k < 3u; k++) {
    let k1 = (k + 1u) % 3u;
    let k2 = (k + 2u) % 3u;
    let P = accPt(o + 5u * k);
    let Ep = accPt(o + 5u * k + 1u);
    let Em1 = accPt(o + 5u * k1 + 2u);
    accTriSlot(k, 4u, 0u, P);
    accTriSlot(k, 3u, 1u, 0.25 * P + 0.75 * Ep);
    accTriSlot(k, 2u, 2u, 0.5 * (Ep + Em1));
    accTriSlot(k, 1u, 3u, 0.75 * Em1 + 0.25 * accPt(o + 5u * k1));
    accTriSlot(k, 2u, 1u, accBlend(accPt(o + 5u * k + 3u), l[k1], accPt(o + 5u * k + 4u), l[k2]));
  }
}

// Sector k of a Pm patch with m sectors into accQ (Myles, Ni, Peters 2008).
fn accPmSector(o: u32, m: u32, k: u32) {
  let kp = (k + m - 1u) % m;
  let kn = (k + 1u) % m;
  let ck = accPt(o + 6u * k);
  let tk = accPt(o + 6u * k + 1u);
  let tk1 = accPt(o + 6u * k + 2u);
  let ck1 = accPt(o + 6u * kn);
  let b211 = accPt(o + 6u * k + 3u);
  let b121 = accPt(o + 6u * k + 4u);
  let b112 = accPt(o + 6u * k + 5u);
  let q310 = 0.25 * ck + 0.75 * tk;
  let q130 = 0.75 * tk1 + 0.25 * ck1;
  accSetQ(4u, 0u, 0u, ck);
  accSetQ(3u, 1u, 0u, q310);
  accSetQ(2u, 2u, 0u, 0.5 * (tk + tk1));
  accSetQ(1u, 3u, 0u, q130);
  accSetQ(0u, 4u, 0u, ck1);
  accSetQ(2u, 1u, 1u, b211);
  accSetQ(1u, 2u, 1u, b121);
  accSetQ(1u, 1u, 2u, b112);
  let prevNear = 0.25 * ck + 0.75 * accPt(o + 6u * kp + 2u); // (c_k + 3 t_k⁻)/4
  let nextNear = 0.25 * ck1 + 0.75 * accPt(o + 6u * kn + 1u); // (c_{k+1} + 3 t_{k+1}⁺)/4
  if (m == 4u) {
    accSetQ(3u, 0u, 1u, 0.5 * (q310 + prevNear));
    accSetQ(0u, 3u, 1u, 0.5 * (q130 + nextNear));
    accSetQ(2u, 0u, 2u, 0.5 * (b211 + accPt(o + 6u * kp + 4u)));
    accSetQ(0u, 2u, 2u, 0.5 * (b121 + accPt(o + 6u * kn + 3u)));
    accSetQ(1u, 0u, 3u, 0.5 * (b112 + accPt(o + 6u * kp + 5u)));
    accSetQ(0u, 1u, 3u, 0.5 * (b112 + accPt(o + 6u * kn + 5u)));
    accSetQ(0u, 0u, 4u, 0.25 * (accPt(o + 5u) + accPt(o + 11u) + accPt(o + 17u) + accPt(o + 23u)));
  } else {
    let q301 = (ck + q310 + prevNear) / 3.0;
    let q031 = (ck1 + q130 + nextNear) / 3.0;
    let q202 = (q301 + b211 + accPt(o + 6u * kp + 4u)) / 3.0;
    let q022 = (q031 + b121 + accPt(o + 6u * kn + 3u)) / 3.0;
    accSetQ(3u, 0u, 1u, q301);
    accSetQ(0u, 3u, 1u, q031);
    accSetQ(2u, 0u, 2u, q202);
    accSetQ(0u, 2u, 2u, q022);
    accSetQ(1u, 0u, 3u, (q202 + b112 + accPt(o + 6u * kp + 5u)) / 3.0);
    accSetQ(0u, 1u, 3u, (q022 + b112 + accPt(o + 6u * kn + 5u)) / 3.0);
    accSetQ(0u, 0u, 4u, accPt(o + 18u));
  }
}

fn accNormal(n: vec3<f32>) -> vec3<f32> {
  let l = length(n);
  if (l > 0.0) { return n / l; }
  return n;
}

// Where the two tangents are parallel (or one vanishes) the patch has no normal of its own: at the
// corner of a crease sector of one face (the face spans the half-disk on its side of the crease, so
// its two edges at the vertex leave it in opposite directions, θ = π) and at a corner sector's
// degenerate corner. The normal there is the patch's own, approached from inside: evaluated
// ACC_DEGENERATE_STEP of the way toward the centroid of the triangle (corner, next corner, patch
// centre), (the same rule as src/subdiv/acc-evaluate.ts AccSurface.evaluate, so the two agree;
// both at f32/f64 noise level there, where the position's own normal would be the noise's
// direction). Not along the diagonal: a Pm patch's sectors meet there (its quads' diagonals, its
// triangles' medians), and f32 rounding would pick either side's normal.
// ACC_DEGENERATE_SIN and ACC_DEGENERATE_STEP (f32) are prepended from src/subdiv/acc.ts
// (src/gpu/acc/patches.ts ACC_SURFACE_WGSL).

fn evalAccPatch(patchId: u32, u: f32, v: f32) -> AccSurfacePoint {
  let tri = accPatchWord(2u * patchId) == 3u || accPatchWord(2u * patchId) >= 5u;
  var at = vec2<f32>(u, v);
  // The next corner counter-clockwise, from a corner (quads (0,0) → (1,0) → (1,1) → (0,1);
  // triangles (0,0) → (1,0) → (0,1)).
  let next = select(vec2<f32>(1.0 - v, u), vec2<f32>(1.0 - u - v, u), tri);
  let centre = select(vec2<f32>(0.5), vec2<f32>(1.0 / 3.0), tri);
  let inward = (at + next + centre) / 3.0 - at;
  var r: AccSurfacePoint;
  // One call site (the evaluator is inlined per call), run a second time only at such a corner.
  for (var i = 0u; i < 2u; i++) {
    let e = accPatchPoint(patchId, at.x, at.y);
    if (i == 0u) {
      r = e;
      let c = cross(e.du, e.dv);
      if (dot(c, c) > ACC_DEGENERATE_SIN * ACC_DEGENERATE_SIN * dot(e.du, e.du) * dot(e.dv, e.dv)) { break; }
      at += ACC_DEGENERATE_STEP * inward;
    } else {
      r.normal = e.normal;
    }
  }
  return r;
}

fn accPatchPoint(patchId: u32, u: f32, v: f32) -> AccSurfacePoint {
  let kind = accPatchWord(2u * patchId);
  let o = accPatchWord(2u * patchId + 1u);
  if (kind <= 2u) {
    if (kind == 2u) {
      accGregoryQuad(o, u, v);
    } else {
      for (var i = 0u; i < 16u; i++) { accQ[i] = accPt(o + i); }
    }
    let r = accBicubic(u, v);
    var tu = r[1];
    var tv = r[2];
    if (kind == 1u) {
      // Tangent patches: T_u quadratic in u × cubic in v, T_v cubic in u × quadratic in v; middle
      // rows from the geometry patch (Loop & Schaefer 2008).
      let b2u = accBern2(u);
      let b2v = accBern2(v);
      let b3u = accBern3(u);
      let b3v = accBern3(v);
      var Tu = vec3<f32>(0.0);
      var Tv = vec3<f32>(0.0);
      for (var c = 0u; c < 4u; c++) {
        Tu += b3v[c] * (b2u[0] * accPt(o + 16u + c) + b2u[1] * 3.0 * (accQ[2u + 4u * c] - accQ[1u + 4u * c]) + b2u[2] * accPt(o + 20u + c));
        Tv += b3u[c] * (b2v[0] * accPt(o + 24u + c) + b2v[1] * 3.0 * (accQ[c + 8u] - accQ[c + 4u]) + b2v[2] * accPt(o + 28u + c));
      }
      tu = Tu;
      tv = Tv;
    }
    return AccSurfacePoint(r[0], accNormal(cross(tu, tv)), tu, tv);
  }
  var stw: vec3<f32>;
  var du: vec3<f32>;
  var dv: vec3<f32>;
  if (kind == 3u) {
    let l = vec3<f32>(1.0 - u - v, u, v);
    accGregoryTri(o, l);
    stw = l;
    du = vec3<f32>(-1.0, 1.0, 0.0);
    dv = vec3<f32>(-1.0, 0.0, 1.0);
  } else if (kind == 4u) {
    var k: u32;
    if (v <= u) {
      if (u + v <= 1.0) { k = 0u; stw = vec3<f32>(1.0 - u - v, u - v, 2.0 * v); du = vec3<f32>(-1.0, 1.0, 0.0); dv = vec3<f32>(-1.0, -1.0, 2.0); }
      else { k = 1u; stw = vec3<f32>(u - v, u + v - 1.0, 2.0 - 2.0 * u); du = vec3<f32>(1.0, 1.0, -2.0); dv = vec3<f32>(-1.0, 1.0, 0.0); }
    } else {
      if (u + v > 1.0) { k = 2u; stw = vec3<f32>(u + v - 1.0, v - u, 2.0 - 2.0 * v); du = vec3<f32>(1.0, -1.0, 0.0); dv = vec3<f32>(1.0, 1.0, -2.0); }
      else { k = 3u; stw = vec3<f32>(v - u, 1.0 - u - v, 2.0 * u); du = vec3<f32>(-1.0, -1.0, 2.0); dv = vec3<f32>(1.0, -1.0, 0.0); }
    }
    accPmSector(o, 4u, k);
  } else {
    let l0 = 1.0 - u - v;
    var k: u32;
    if (l0 >= v && u >= v) { k = 0u; stw = vec3<f32>(l0 - v, u - v, 3.0 * v); du = vec3<f32>(-1.0, 1.0, 0.0); dv = vec3<f32>(-2.0, -1.0, 3.0); }
    else if (v > l0 && u >= l0) { k = 1u; stw = vec3<f32>(u - l0, v - l0, 3.0 * l0); du = vec3<f32>(2.0, 1.0, -3.0); dv = vec3<f32>(1.0, 2.0, -3.0); }
    else { k = 2u; stw = vec3<f32>(v - u, l0 - u, 3.0 * u); du = vec3<f32>(-1.0, -2.0, 3.0); dv = vec3<f32>(1.0, -1.0, 0.0); }
    accPmSector(o, 3u, k);
  }
  let e = accQuartic(stw.x, stw.y, stw.z);
  let Pu = 4.0 * (du.x * e[1] + du.y * e[2] + du.z * e[3]);
  let Pv = 4.0 * (dv.x * e[1] + dv.y * e[2] + dv.z * e[3]);
  return AccSurfacePoint(e[0], accNormal(cross(Pu, Pv)), Pu, Pv);
}
