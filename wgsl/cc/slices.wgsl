// The fans' slices, as the patch build writes them (wgsl/cc/build.wgsl) and the evaluator reads
// them (wgsl/cc/surface.wgsl): one file, so that a step made again by the evaluator is the slice
// kernel's own step. Layout: src/gpu/cc/build.ts "slices"; both shaders bind `params`,
// `staticBuf` and `cageBuf` and prepend the packed words' getters.

// A point of the Catmull-Clark point space: the cage's, else a refined one (levels, slices, limits).
fn ccP(p: u32) -> vec3<f32> {
  let o = select(params.offCtrl + 3u * (p - params.ccCageVerts), 3u * p, p < params.ccCageVerts);
  return vec3<f32>(cageBuf[o], cageBuf[o + 1u], cageBuf[o + 2u]);
}

fn ccFanWord(fan: u32, i: u32) -> u32 { return staticBuf[params.ccFans + CC_FAN_WORDS * fan + i]; }

// A fan's slices: sectors (threads), valence, boundary, first point, its sector words, depth D,
// and whether it keeps its odd steps' sector points only.
struct CCFan { ns: u32, n: u32, boundary: bool, base: u32, sectors: u32, D: u32, odd: bool }

fn ccFan(fan: u32) -> CCFan {
  let w = ccFanWord(fan, 0u);
  return CCFan(ccFanWord_sectors(w), ccFanWord_valence(w), ccFanWord_boundary(w) == 1u, ccFanWord(fan, 2u),
               params.ccSectors + ccFanWord(fan, 3u), ccFanWord_depth(w), ccFanWord_odd(w) == 1u);
}

// Sector j + d: wrapping round an interior fan; on a boundary fan clamped to 0..n (n: the
// pseudo-sector of the last axis). The slice kernel's neighbours: a boundary's sector 0 is its
// own previous one and the pseudo-sector its own next (their crease rules read nothing there);
// where a sub-patch reads past them, the phantom rule discards the points.
fn ccNb(f: CCFan, j: u32, d: i32) -> u32 {
  let m = i32(j) + d;
  if (f.boundary) { return u32(clamp(m, 0, i32(f.n))); }
  let n = i32(f.n);
  return u32(((m % n) + n) % n);
}

// An axis's sharpness after `decays` levels below the fan's start, from its axis word (src/gpu/cc/
// build.ts "sectors"): 0 smooth, AXIS_INFINITE when infinitely sharp, else σ − decays (≤ 0 once
// it has decayed: smooth). Uniform creasing: one unit of sharpness a level.
const AXIS_INFINITE: f32 = 3.0e38;
fn ccAxisSharpness(w: u32, decays: u32) -> f32 {
  if (w == CC_AXIS_INFINITE) { return AXIS_INFINITE; }
  return select(bitcast<f32>(w) - f32(decays), 0.0, w == 0u);
}
fn ccAxisSharp(f: CCFan, sec: u32, decays: u32) -> f32 { return ccAxisSharpness(staticBuf[f.sectors + 7u * sec], decays); }

// Whether step k's sector points are stored (every step's; an odd fan's odd steps'), and where
// they start (sector j's 12 at 12j after it). The centres of every step are stored.
fn ccSliceStored(f: CCFan, k: u32) -> bool { return !f.odd || (k & 1u) == 1u; }
fn ccSliceStepBase(f: CCFan, k: u32) -> u32 { return f.base + f.D + 12u * f.ns * select(k - 1u, (k - 1u) / 2u, f.odd); }

// One step of one sector: its 12 new points (a, b), a ∈ 1..3, b ∈ 0..3, at 4(a − 1) + b, from
// its 6 old points p, the old centre c, the next sector's (1,0), (2,0) (n10, n20) and the
// previous one's (1,0), (1,1), (1,2) (q10, q11, q12). The face points of the cells
// are made here from those (the previous sector's two cells along this sector's axis too), so
// a sector needs no other thread's results, only their old points. sigma: this sector's axis's
// sharpness before the step (ccAxisSharpness); pseudo: a boundary's pseudo-sector (its axis
// points only).
fn sliceStep(p: array<vec3<f32>, 6>, c: vec3<f32>, n10: vec3<f32>, n20: vec3<f32>, q10: vec3<f32>, q11: vec3<f32>, q12: vec3<f32>,
             sigma: f32, pseudo: bool) -> array<vec3<f32>, 12> {
  let p10 = p[0];
  let p20 = p[1];
  let p11 = p[2];
  let p21 = p[3];
  let p12 = p[4];
  let p22 = p[5];
  let f00 = 0.25 * (c + p10 + p11 + n10);
  let f10 = 0.25 * (p10 + p20 + p21 + p11);
  let f01 = 0.25 * (n10 + p11 + p12 + n20);
  let f11 = 0.25 * (p11 + p21 + p22 + p12);
  // The previous sector's cells 00 and 01: this sector's [0,1]×[−1,0] and [1,2]×[−1,0].
  let g00 = 0.25 * (c + q10 + q11 + p10);
  let g01 = 0.25 * (p10 + q11 + q12 + p20);
  var o: array<vec3<f32>, 12>;
  // Axis i, by its sharpness σ (the rules of the levels, wgsl/cc/build.wgsl `points`: OpenSubdiv's
  // uniform creasing): its two edge points crease from σ ≥ 1, smooth at σ ≤ 0, between them the
  // blend by σ; its vertex point (1,0), whose two axis halves have the one σ (the fan's
  // eligibility), crease while the axis stays sharp after the step (σ > 1), smooth at σ ≤ 0,
  // between them the crease rule blended with the smooth by OpenSubdiv's W, which is σ here.
  let e0 = 0.25 * (c + p10 + f00 + g00);
  let e0c = 0.5 * (c + p10);
  let e1 = 0.25 * (p10 + p20 + f10 + g01);
  let e1c = 0.5 * (p10 + p20);
  let v = 0.5 * p10 + 0.0625 * (c + p20 + p11 + q11) + 0.0625 * (f00 + f10 + g00 + g01);
  let vc = 0.75 * p10 + 0.125 * (c + p20);
  o[0] = select(select(sigma * e0c + (1.0 - sigma) * e0, e0c, sigma >= 1.0), e0, sigma <= 0.0);
  o[8] = select(select(sigma * e1c + (1.0 - sigma) * e1, e1c, sigma >= 1.0), e1, sigma <= 0.0);
  o[4] = select(select(sigma * vc + (1.0 - sigma) * v, vc, sigma > 1.0), v, sigma <= 0.0);
  if (!pseudo) {
    o[1] = f00;
    o[9] = f10;
    o[3] = f01;
    o[11] = f11;
    o[5] = 0.25 * (p10 + p11 + f00 + f10);   // (2,1)
    o[2] = 0.25 * (n10 + p11 + f00 + f01);   // (1,2)
    o[10] = 0.25 * (p11 + p21 + f10 + f11);  // (3,2)
    o[7] = 0.25 * (p11 + p12 + f01 + f11);   // (2,3)
    o[6] = 0.5 * p11 + 0.0625 * (p10 + p21 + p12 + n10) + 0.0625 * (f00 + f10 + f01 + f11); // (2,2)
  }
  return o;
}

// Old point j ((1,0) (2,0) (1,1) (2,1) (1,2) (2,2): the step's 0, 4, 1, 5, 2, 6) of sector `sec`
// before step k, as an offset from the fan's anchor: the start level's (its sector words) at
// k = 1, else step k − 1's, which must be stored.
fn ccSliceOld(f: CCFan, anchor: vec3<f32>, k: u32, sec: u32, j: u32) -> vec3<f32> {
  if (k == 1u) { return ccP(staticBuf[f.sectors + 7u * sec + 1u + j]) - anchor; }
  let at = array<u32, 6>(0u, 4u, 1u, 5u, 2u, 6u);
  return ccP(ccSliceStepBase(f, k - 1u) + 12u * sec + at[j]);
}

// Sector sec's 12 points of step k made from the step before in memory (stored, or the start
// level's): a wide fan's steps (the slice kernel, wgsl/cc/build.wgsl wideSlices), and an odd
// fan's even steps where they are read (the limits kernel, the evaluator).
fn ccSliceMake(f: CCFan, anchor: vec3<f32>, k: u32, sec: u32) -> array<vec3<f32>, 12> {
  let prev = ccNb(f, sec, -1);
  let next = ccNb(f, sec, 1);
  let c = select(ccP(f.base + k - 2u), vec3<f32>(0.0), k == 1u);
  var p: array<vec3<f32>, 6>;
  for (var j = 0u; j < 6u; j++) { p[j] = ccSliceOld(f, anchor, k, sec, j); }
  return sliceStep(p, c, ccSliceOld(f, anchor, k, next, 0u), ccSliceOld(f, anchor, k, next, 1u),
                   ccSliceOld(f, anchor, k, prev, 0u), ccSliceOld(f, anchor, k, prev, 2u), ccSliceOld(f, anchor, k, prev, 4u),
                   ccAxisSharp(f, sec, k - 1u), f.boundary && sec == f.n);
}
