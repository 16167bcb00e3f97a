// One semi-sharp crease on a bicubic B-spline patch's u = 0 side, in closed form, f32
// (Nießner, Loop, Greiner 2012). The f64 twin, with
// the derivation in its comments, is src/subdiv/crease-basis.ts: keep the two in step.
// Self-contained: no bindings, no other module; every name starts with `crease`.
//
// API
//   struct CreaseWeights { value: vec4<f32>, du: vec4<f32> }
//   fn creaseRowWeights(sigma: f32, u: f32) -> CreaseWeights
//     Weights on one row b0..b3 across the crease: b1 ON the crease (u = 0), b0 across it,
//     b2, b3 inside the patch. value(u) = Σ value[i]·b_i, d/du = Σ du[i]·b_i.
//     sigma: OpenSubdiv sharpness as stored (f32): ≤ 0 smooth (plain B-spline),
//     ≥ 10 infinitely sharp (phantom b0 = 2 b1 − b2). u ∈ [0,1].
//   fn creaseBSplineWeights(t: f32) -> CreaseWeights      (the plain cubic B-spline)
//
// Patch use (layout: cp[4r + c], row r ~ v, column c ~ u, crease on column 1 after the
// caller's rotation). The crease changes the u basis only, so the separable evaluation stays:
//   let wu = creaseRowWeights(sigma, u);
//   let wv = creaseBSplineWeights(v);
//   col[c]  = Σ_r wv.value[r]·cp[4r + c]      colV[c] = Σ_r wv.du[r]·cp[4r + c]
//   P       = Σ_c wu.value[c]·col[c]
//   dP/du   = Σ_c wu.du[c]·col[c]               dP/dv = Σ_c wu.value[c]·colV[c]
//   (sub-patch derivative scaling by 2^L as for any patch).
//
// Why weights and not the 4×4 matrix: the matrix M = A⁻¹·diag(1, 2^k, 4^k, 8^k)·A·L^k has
// entries growing like 8^k (≈ 1933 at k = 5). Every weight here is
// bounded by 2 in magnitude, value and d/du alike, and 2^-k and u·2^k are exact (ldexp).
// Agreement with the f64 twin: ≤ 1e-6 absolute per weight (tests/gpu/cc/crease-basis.gpu.test.ts).

struct CreaseWeights {
  value: vec4<f32>,
  du: vec4<f32>,
}

const CREASE_SHARPNESS_INFINITE: f32 = 10.0;

fn creaseBSplineWeights(t: f32) -> CreaseWeights {
  let s = 1.0 - t;
  let t2 = t * t;
  let t3 = t2 * t;
  let b = vec4<f32>(s * s * s, 3.0 * t3 - 6.0 * t2 + 4.0, -3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0, t3) / 6.0;
  let d = vec4<f32>(-0.5 * s * s, 0.5 * (3.0 * t2 - 4.0 * t), 0.5 * (-3.0 * t2 + 2.0 * t + 1.0), 0.5 * t2);
  return CreaseWeights(b, d);
}

// C(phantom row, u), phantom = (2 b1 − b2, b1, b2, b3): the infinitely sharp row (OpenSubdiv's phantom point).
fn creasePhantomWeights(u: f32) -> CreaseWeights {
  let B = creaseBSplineWeights(u);
  return CreaseWeights(
    vec4<f32>(0.0, 2.0 * B.value.x + B.value.y, B.value.z - B.value.x, B.value.w),
    vec4<f32>(0.0, 2.0 * B.du.x + B.du.y, B.du.z - B.du.x, B.du.w));
}

// C(level-k row, u·2^k) with r = 2^-k, valid on u ∈ [0, r]: the B-spline of the polygon after
// k sharp steps, in terms of the original row:
//   c0 = r b0 + (1−r) b1,  c1 = b1,  c2 = (1−r) b1 + r b2,  c3 = (1 − 2r + r³) b1 + (2r − 2r³) b2 + r³ b3.
// d/du includes the 1/r of the local parameter, cancelled against the r of each term; b1's
// d/du weight is minus the others' sum (Σ B' = 0), so no 2^k-scaled cancellation happens.
fn creaseLevelWeights(k: i32, u: f32) -> CreaseWeights {
  let r = ldexp(1.0, -k);
  let B = creaseBSplineWeights(ldexp(u, k));
  let r2 = r * r;
  let r3 = r2 * r;
  let q = 1.0 - r;
  let w = vec4<f32>(
    r * B.value.x,
    q * B.value.x + B.value.y + q * B.value.z + (1.0 - 2.0 * r + r3) * B.value.w,
    r * B.value.z + (2.0 * r - 2.0 * r3) * B.value.w,
    r3 * B.value.w);
  let d0 = B.du.x;
  let d2 = B.du.z + (2.0 - 2.0 * r2) * B.du.w;
  let d3 = r2 * B.du.w;
  return CreaseWeights(w, vec4<f32>(d0, -(d0 + d2 + d3), d2, d3));
}

// σ = k + f (k = ⌊σ⌋, f exact), r = 2^-k:
//   u ≥ r        : phantom                    (k = 0: only u = 1, where all pieces agree)
//   f = 0, u < r : level-k
//   f > 0        : r/2 ≤ u < r : f·phantom + (1−f)·level-k
//                  u < r/2     : f·level-(k+1) + (1−f)·level-k
fn creaseRowWeights(sigma: f32, u: f32) -> CreaseWeights {
  if (!(sigma > 0.0)) {
    return creaseBSplineWeights(u);
  }
  if (sigma >= CREASE_SHARPNESS_INFINITE) {
    return creasePhantomWeights(u);
  }
  let kf = floor(sigma);
  let f = sigma - kf;
  let k = i32(kf);
  if (u >= ldexp(1.0, -k)) {
    return creasePhantomWeights(u);
  }
  let a = creaseLevelWeights(k, u);
  if (f == 0.0) {
    return a;
  }
  var b: CreaseWeights;
  if (u >= ldexp(1.0, -k - 1)) {
    b = creasePhantomWeights(u);
  } else {
    b = creaseLevelWeights(k + 1, u);
  }
  return CreaseWeights(f * b.value + (1.0 - f) * a.value, f * b.du + (1.0 - f) * a.du);
}
