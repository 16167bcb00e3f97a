// The ACC error views' pass over the compute tessellator's output vertices (src/gpu/acc/heat.ts):
// per vertex, the distance from the ACC surface to the exact Catmull-Clark limit at the vertex's
// own cage parameter (srcTri, bary), as a fraction of the cage's diagonal, and the angle between
// their normals in degrees; then max and sum of squares per workgroup, and one workgroup that
// folds those into the totals the stats read back.
//
// Prepended: tessPrelude(TESS_INPUTS) (the reference Catmull-Clark tessellator's params, staticBuf,
// cageBuf, work), wgsl/tess/common.wgsl, the exact surface (evalSurface), the ACC bindings and
// evaluator (evalAccPatch), the generated HeatPass struct and constants (src/gpu/acc/heat.ts) and
// this pass's bindings (HEAT_GROUP, src/gpu/contract/acc.ts: srcTri, bary, aux, heatPass,
// outCounts, dispatchArgs).
//
// aux (HEAT_AUX in src/gpu/acc/heat.ts, offsets in `heatPass`): the header (vertex count, workgroups, the
// totals), the ACC_TRI_WORD of each cage triangle, per-workgroup partials and the per-vertex
// values the lit pass reads (2 f32 each, as u32 bits).


var<workgroup> wgMax: array<vec2<f32>, WORKGROUP_SIZE>;
var<workgroup> wgSum: array<vec2<f32>, WORKGROUP_SIZE>;
var<workgroup> wgCount: array<u32, WORKGROUP_SIZE>;

fn vertexCount() -> u32 { return aux[heatPass.offHeader + HEADER_COUNT]; }

// (distance / diagonal, degrees) at output vertex i; x < 0 for a vertex no triangle uses.
fn vertexError(i: u32) -> vec2<f32> {
  let t = srcTri[i];
  if (t == NO_OWNER) { return vec2<f32>(-1.0, 0.0); }
  let b = bary[i];
  var w1 = baryWord_w1(b);
  var w2 = baryWord_w2(b);
  if (b == BARY_CORNER1) { w1 = ONE; w2 = 0u; }
  if (b == BARY_CORNER2) { w1 = 0u; w2 = ONE; }
  let m = aux[heatPass.offTriMap + t];
  let accPatch = accTriWord_face(m);
  // Regular patches are the bicubic B-spline itself in every scheme (f64 error
  // ≤ 1e-15 in tests/gpu/acc/acc.test.ts): what the two f32 evaluators would differ by there is their
  // own rounding, not the scheme's error, so they show the sample's zero.
  if (accPatchWord(2u * accPatch) == KIND_REGULAR) { return vec2<f32>(0.0); }
  let exact = evalSurface(t, vec3<u32>(ONE - w1 - w2, w1, w2));
  let c = accTriWord_corners(m);
  let w = vec3<f32>(f32(ONE - w1 - w2), f32(w1), f32(w2)) / f32(ONE);
  let uc = vec3<f32>(f32(accTriCorners_u0(c)), f32(accTriCorners_u1(c)), f32(accTriCorners_u2(c)));
  let vc = vec3<f32>(f32(accTriCorners_v0(c)), f32(accTriCorners_v1(c)), f32(accTriCorners_v2(c)));
  let a = evalAccPatch(accPatch, dot(w, uc), dot(w, vc));
  let d = length(a.pos - exact.pos) * heatPass.invDiag;
  // atan2(|n × m|, n · m): accurate near 0 (acos is not, in f32); 0 where either normal is 0.
  let deg = degrees(atan2(length(cross(a.normal, exact.normal)), dot(a.normal, exact.normal)));
  return vec2<f32>(d, deg);
}

@compute @workgroup_size(WORKGROUP_SIZE)
fn heatErrors(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let g = wid.y * GRID_X + wid.x;
  let i = g * WORKGROUP_SIZE + lid;
  var e = vec2<f32>(0.0);
  var counted = 0u;
  if (i < vertexCount()) {
    let r = vertexError(i);
    if (r.x >= 0.0) {
      e = r;
      counted = 1u;
    }
    aux[heatPass.offErrors + 2u * i] = bitcast<u32>(e.x);
    aux[heatPass.offErrors + 2u * i + 1u] = bitcast<u32>(e.y);
  }
  wgMax[lid] = e;
  wgSum[lid] = e * e;
  wgCount[lid] = counted;
  workgroupBarrier();
  for (var s = WORKGROUP_SIZE / 2u; s > 0u; s >>= 1u) {
    if (lid < s) {
      wgMax[lid] = max(wgMax[lid], wgMax[lid + s]);
      wgSum[lid] += wgSum[lid + s];
      wgCount[lid] += wgCount[lid + s];
    }
    workgroupBarrier();
  }
  if (lid == 0u && g < aux[heatPass.offHeader + HEADER_GROUPS]) {
    let o = heatPass.offPartials + PARTIAL_WORDS * g;
    aux[o] = bitcast<u32>(wgMax[0].x);
    aux[o + 1u] = bitcast<u32>(wgSum[0].x);
    aux[o + 2u] = bitcast<u32>(wgMax[0].y);
    aux[o + 3u] = bitcast<u32>(wgSum[0].y);
    aux[o + 4u] = wgCount[0];
  }
}

// One workgroup: the partials folded into the header's totals (max, Σ², max, Σ², count).
@compute @workgroup_size(WORKGROUP_SIZE)
fn heatTotals(@builtin(local_invocation_index) lid: u32) {
  let groups = aux[heatPass.offHeader + HEADER_GROUPS];
  var mx = vec2<f32>(0.0);
  var sm = vec2<f32>(0.0);
  var n = 0u;
  for (var g = lid; g < groups; g += WORKGROUP_SIZE) {
    let o = heatPass.offPartials + PARTIAL_WORDS * g;
    mx = max(mx, vec2<f32>(bitcast<f32>(aux[o]), bitcast<f32>(aux[o + 2u])));
    sm += vec2<f32>(bitcast<f32>(aux[o + 1u]), bitcast<f32>(aux[o + 3u]));
    n += aux[o + 4u];
  }
  wgMax[lid] = mx;
  wgSum[lid] = sm;
  wgCount[lid] = n;
  workgroupBarrier();
  for (var s = WORKGROUP_SIZE / 2u; s > 0u; s >>= 1u) {
    if (lid < s) {
      wgMax[lid] = max(wgMax[lid], wgMax[lid + s]);
      wgSum[lid] += wgSum[lid + s];
      wgCount[lid] += wgCount[lid + s];
    }
    workgroupBarrier();
  }
  if (lid == 0u) {
    let o = heatPass.offHeader + HEADER_TOTALS;
    aux[o] = bitcast<u32>(wgMax[0].x);
    aux[o + 1u] = bitcast<u32>(wgSum[0].x);
    aux[o + 2u] = bitcast<u32>(wgMax[0].y);
    aux[o + 3u] = bitcast<u32>(wgSum[0].y);
    aux[o + 4u] = wgCount[0];
  }
}

// One thread, before the two passes above: the vertex count of the output's accepted build (its
// counts word 0, clamped to the capacity the values have room for), the workgroups that cover it,
// and heatErrors' indirect dispatch (GRID_X wide, as grid2d).

@compute @workgroup_size(1)
fn heatArgs() {
  let n = min(outCounts[0], heatPass.capacity);
  let groups = (n + WORKGROUP_SIZE - 1u) / WORKGROUP_SIZE;
  aux[heatPass.offHeader + HEADER_COUNT] = n;
  aux[heatPass.offHeader + HEADER_GROUPS] = groups;
  dispatchArgs[0] = min(groups, GRID_X);
  dispatchArgs[1] = (groups + GRID_X - 1u) / GRID_X;
  dispatchArgs[2] = 1u;
}
