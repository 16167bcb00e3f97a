// The adaptive factor rule's bulge term: one thread per cage triangle, once per rebuild before the
// budget attempts (the term does not depend on the attempt). Its double-precision twin, and why
// the rule needs it, is src/gpu/tess/factors.ts bulgeFactor; the constants must match it
// (tests/gpu/tess/factors.test.ts reads them from this file).
//
// The edge term (wgsl/tess/factor-rule.wgsl) sees only each edge's ends. Inside a cage triangle whose edges
// are nearly straight the surface can still bulge, and the clamped pattern puts no interior
// vertex there below a factor of about 3, so the drawn triangles cut through the bulge (pixels
// off the limit in the demo's first view, and silhouettes short of it). So the surface is sampled
// at BULGE_SAMPLES points of the triangle (three points (2/3, 1/6, 1/6), then the centroid); at
// each the bulge is its distance from the flat triangle of the corners at the same weights, in
// pixels at its distance from the eye, and it asks for k = sqrt(BULGE_ALPHA · lodScale · bulge px).
// The triangle stores the largest k, or BULGE_OFF_SCREEN where its sphere (round the flat
// centroid through the farthest corner, grown by the largest bulge) is outside the frustum.
// Facing away does not lower it: a triangle facing away beside one facing the eye would keep an
// edge at 1 beside edges at 14, and such strips fold. Each edge then takes the larger k of its
// two triangles (wgsl/tess/factors.wgsl adaptiveFactor), so the factor stays one per edge and
// continuous in the camera.
const BULGE_ALPHA: f32 = 10.0;
const BULGE_SAMPLES: u32 = 4u;
const BULGE_OFF_SCREEN: f32 = -1.0;

// Sample i of a triangle, in 16.16 barycentrics: corner-heavy points for i < 3, then the centroid.
fn bulgeWeights(i: u32) -> vec3<u32> {
  if (i == 3u) { return vec3<u32>(ONE / 3u, ONE / 3u, ONE - 2u * (ONE / 3u)); }
  var w = vec3<u32>(ONE / 6u);
  w[i] = ONE - 2u * (ONE / 6u);
  return w;
}

// The turn term, for a surface whose normal can turn faster inside an edge than between its ends
// (SURFACE_NORMAL_TURNS: Catmull-Clark and its approximations; Phong's normal is interpolated, so
// the edge term sees its whole turn). Why: a thin fold of the cage gives the limit surface a
// hairpin, a turn of 90-150° across a strip a few hundredths of the face wide (bigguy's brow:
// 94° within 0.02 of face 640 from its edge; the creature's face 476: 98° between v = 0.32 and
// 0.36). The chord and bulge terms are met there (the strip is under a pixel), so one row of the
// pattern spans the whole turn, and a triangle with two corners on the turned side faces against
// the sum of its corners' normals (bigguy: 746 such triangles over the 30 views of
// scripts/folds.ts). So each edge asks for enough segments that the normal turns at most
// TURN_PER_SEGMENT across one, from its steepest turn between the TURN_SAMPLES + 1 points along it
// (a turn narrower than a sample step counts in full over that step). Edges that cross a hairpin
// get the rows that resolve it; the edges along it need none. Over a circular arc a triangle
// folds only past 180°; these hairpins fold from about 130°. Measured over those views (bigguy,
// the creature, imrod: folded triangles and the change in triangles): 120°: 746 → 101, 130 → 68,
// 74 → 35, +4.4 %, +0.2 %, +3.5 %; 90°: 139, 48, 75 (imrod's slivers doubled), +7.5 %, +0.7 %,
// +9.3 %. The term depends on the surface alone, not the camera, so it is computed when the
// surface changes (Params.turnRefresh: once per cage, and again after updateCage), and capped per
// edge by its pixels in the factor rule (TURN_PIXELS).
const TURN_SAMPLES: u32 = 32u;
const TURN_PER_SEGMENT: f32 = 2.0943951; // 120°

// The angle between two normals; 0 where either is missing (a degenerate corner has none).
fn turnBetween(a: vec3<f32>, b: vec3<f32>) -> f32 {
  let ok = all(a == a) && all(b == b) && dot(a, a) > 0.25 && dot(b, b) > 0.25;
  return select(0.0, atan2(length(cross(a, b)), dot(a, b)), ok);
}

// Sample k of an edge's turn, as corner j's 16.16 weight: the corner, 1/256 from it, the
// TURN_SAMPLES − 1 inner points, 1/256 from the other corner, the other corner.
fn turnSampleAt(k: u32) -> u32 {
  let near = ONE / 256u;
  if (k == 0u) { return 0u; }
  if (k == 1u) { return near; }
  if (k == TURN_SAMPLES + 1u) { return ONE - near; }
  if (k == TURN_SAMPLES + 2u) { return ONE; }
  return (k - 1u) * (ONE / TURN_SAMPLES);
}

// The turn over the sample step next to a corner (normal c), to the first inner point (m), with
// the point 1/256 from the corner (e). Where the normal jumps at the corner (a cone point, which
// has no limit normal: it turns by as much in that 1/256 as over the whole step) rows cannot
// resolve it: the jump is left out and the step's turn beyond it counts.
fn cornerStepTurn(c: vec3<f32>, e: vec3<f32>, m: vec3<f32>) -> f32 {
  let whole = turnBetween(c, m);
  return select(whole, turnBetween(e, m), turnBetween(c, e) > 0.5 * whole);
}

fn edgeTurnSegments(t: u32, i: u32) -> f32 {
  let j = (i + 1u) % 3u;
  var corner = vec3<f32>(0.0);
  var near = vec3<f32>(0.0);
  var prev = vec3<f32>(0.0);
  var most = 0.0;
  // One call of the surface (the evaluator is large: each call site is inlined).
  for (var k = 0u; k <= TURN_SAMPLES + 2u; k++) {
    var w = vec3<u32>(0u);
    w[j] = turnSampleAt(k);
    w[i] = ONE - w[j];
    let n = unblendedSurface(t, w).normal;
    if (k == 0u || k == TURN_SAMPLES + 2u) {
      corner = n;
    } else if (k == 1u || k == TURN_SAMPLES + 1u) {
      near = n;
    }
    if (k == 2u) {
      most = cornerStepTurn(corner, near, n);
    } else if (k > 2u && k <= TURN_SAMPLES) {
      most = max(most, turnBetween(prev, n));
    } else if (k == TURN_SAMPLES + 2u) {
      most = max(most, cornerStepTurn(corner, near, prev));
    }
    if (k >= 2u && k <= TURN_SAMPLES) { prev = n; }
  }
  return f32(TURN_SAMPLES) * most / TURN_PER_SEGMENT;
}

@compute @workgroup_size(WORKGROUP_SIZE)
fn bulge(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let t = flatIndex(wid, lid);
  if (t >= params.nTris) { return; }
  // Fixed factors (mode 0) do not read it: no surface evaluations there.
  if (params.mode == 0u) {
    work[params.offTriBulge + t] = bitcast<u32>(BULGE_OFF_SCREEN);
    return;
  }
  // Each edge's turn term, by its owner, when the surface has changed.
  if (params.turnRefresh != 0u) {
    for (var i = 0u; i < 3u; i++) {
      let e = triEdge(t, i);
      if (ownerWord_tri(staticBuf[params.offEdgeOwner + e]) == t) {
        work[params.offEdgeTurn + e] = bitcast<u32>(select(0.0, edgeTurnSegments(t, i), SURFACE_NORMAL_TURNS));
      }
    }
  }
  let p0 = factorPos(triVert(t, 0u));
  let p1 = factorPos(triVert(t, 1u));
  let p2 = factorPos(triVert(t, 2u));
  var k = 0.0;
  var most = 0.0;
  for (var i = 0u; i < BULGE_SAMPLES; i++) {
    let w = bulgeWeights(i);
    let s = unblendedSurface(t, w);
    let wf = vec3<f32>(w) / 65536.0;
    let b = length(s.pos - (wf.x * p0 + wf.y * p1 + wf.z * p2));
    most = max(most, b);
    let dist = max(length(s.pos - params.eye.xyz), 1e-6);
    k = max(k, sqrt(BULGE_ALPHA * params.lodScale * b / (dist * params.pixelAngle)));
  }
  let c = (p0 + p1 + p2) / 3.0;
  let r = max(max(length(p0 - c), length(p1 - c)), length(p2 - c)) + most;
  if (sphereOutsideFrustum(c, r)) { k = BULGE_OFF_SCREEN; }
  work[params.offTriBulge + t] = bitcast<u32>(k);
}
