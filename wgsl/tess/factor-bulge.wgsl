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

@compute @workgroup_size(WORKGROUP_SIZE)
fn bulge(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let t = flatIndex(wid, lid);
  if (t >= params.nTris) { return; }
  // Fixed factors (mode 0) do not read it: no surface evaluations there.
  if (params.mode == 0u) {
    work[params.offTriBulge + t] = bitcast<u32>(BULGE_OFF_SCREEN);
    return;
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
