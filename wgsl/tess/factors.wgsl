// An edge's tess factor, line state and segment count at a budget candidate, for the count pass
// (wgsl/tess/count.wgsl), which computes each triangle's three edges: both triangles of an edge
// run this same code on the same inputs, so they cannot disagree, and the edge's owner stores it.
// Mirrors src/gpu/tess/factors.ts edgeFactor; the curvature measure is wgsl/tess/factor-rule.wgsl's, and the
// bulge term of the edge's two triangles is wgsl/tess/factor-bulge.wgsl's (its pass has run).

fn sphereOutsideFrustum(c: vec3<f32>, r: f32) -> bool {
  let m = transpose(params.viewProj); // rows of viewProj
  let planes = array<vec4<f32>, 6>(m[3] + m[0], m[3] - m[0], m[3] + m[1], m[3] - m[1], m[2], m[3] - m[2]);
  for (var i = 0u; i < 6u; i++) {
    let p = planes[i];
    if (dot(p.xyz, c) + p.w < -r * length(p.xyz)) { return true; }
  }
  return false;
}

// Screen pixels per segment where a height map's detail is visible (adaptiveFactor).
const DETAIL_PIXELS = 2.0;
// Segments per screen pixel of an edge that its normal's turn may ask for at most.
const TURN_PIXELS = 8.0;

fn adaptiveFactor(e: u32) -> f32 {
  let a = edgeVert(e, 0u);
  let b = edgeVert(e, 1u);
  let p0 = factorPos(a);
  let p1 = factorPos(b);
  let n0 = factorNormal(a);
  let n1 = factorNormal(b);
  let bend = edgeBend(p0, n0, p1, n1, params.eye.xyz);
  // Displacement (src/gpu/tess/displacement-map.ts): the heights on the edge's faces lie in
  // [lo, hi]·scale after the mid level; the sphere grows by the largest |h|, and the edge gets at
  // least as many segments as its height variation spans pixels (times lodScale), up to two per
  // texel along it (the talk's "1 texel = 2 triangles"): detail a pixel or more high is sampled.
  var reach = 0.0;
  var amplitude = 0.0;
  var texels = 0.0;
  if (params.dispOn != 0u) {
    let lo = bitcast<f32>(staticBuf[params.offDispEdge + 3u * e]);
    let hi = bitcast<f32>(staticBuf[params.offDispEdge + 3u * e + 1u]);
    texels = bitcast<f32>(staticBuf[params.offDispEdge + 3u * e + 2u]);
    reach = abs(params.dispScale) * max(abs(lo - params.dispMid), abs(hi - params.dispMid));
    amplitude = abs(params.dispScale) * (hi - lo);
  }
  // The bulge term of the edge's triangles (BULGE_OFF_SCREEN where both are off screen): an edge
  // whose ends face away, or whose own sphere is off screen, still splits while a triangle beside
  // it is on screen (a silhouette inside it; an edge at 1 beside edges at 14 leaves slivers that fold).
  let owner = staticBuf[params.offEdgeOwner + e];
  let twin = staticBuf[params.offEdgeTwin + e];
  var inside = bitcast<f32>(work[params.offTriBulge + ownerWord_tri(owner)]);
  if (twin != NO_OWNER) { inside = max(inside, bitcast<f32>(work[params.offTriBulge + ownerWord_tri(twin)])); }
  let err = length(bend.off);
  let unseen = bend.away || sphereOutsideFrustum(bend.mid, 0.5 * length(p1 - p0) + err + reach);
  if (unseen && inside == BULGE_OFF_SCREEN) { return 1.0; }
  let dist = max(length(bend.mid - params.eye.xyz), 1e-6);
  // The normal's turn (wgsl/tess/factor-bulge.wgsl edgeTurnSegments), at most TURN_PIXELS segments
  // per pixel of the edge's length: far away, a hairpin's rows stop at an eighth of a pixel.
  let turnCap = TURN_PIXELS * length(p1 - p0) / (dist * params.pixelAngle);
  let turn = min(bitcast<f32>(work[params.offEdgeTurn + e]), turnCap);
  let surface = max(max(bendFactor(bend, params.eye.xyz, params.lodScale, params.pixelAngle), inside), turn);
  // The map resolved where it shows: once its heights span a pixel, the edge gets a segment per
  // DETAIL_PIXELS pixels of its own screen length (a brick's mortar line is narrower than its
  // height: counting the height alone left the brick box at ~10 segments an edge, bricks
  // unreadable). Scaled by the heights' span below a pixel, so the factor stays continuous.
  let heightPixels = params.lodScale * amplitude / (dist * params.pixelAngle);
  let edgePixels = params.lodScale * length(p1 - p0) / (dist * params.pixelAngle);
  let resolved = edgePixels / DETAIL_PIXELS * clamp(heightPixels, 0.0, 1.0);
  let detail = min(2.0 * texels, max(heightPixels, resolved));
  return max(surface, detail);
}

// The edge's factor before the budget: the adaptive rule's, or the fixed one.
fn edgeFactor(e: u32) -> f32 {
  return select(adaptiveFactor(e), params.fixedFactor, params.mode == 0u);
}
