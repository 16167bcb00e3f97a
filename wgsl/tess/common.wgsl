// Shared by every tessellation pass. What comes before it is generated from src/gpu/contract/contract.ts
// (tessPrelude, one definition for both sides): `struct Params`, the constants (WORKGROUP_SIZE,
// GRID_X, ONE, NO_OWNER, BUDGET_*, …), the bindings, and the getters of the packed words
// (patternFrameWord_*, baryWord_*, ownerWord_*) and of the table header (tableHeader_*).
//
// Buffers (few, so no pass needs more than 8 storage bindings), each an arena of the contract:
//   staticBuf  TESS_STATIC: the baked pattern tables (src/pattern/tables.ts layout), the mesh's
//              topology (src/gpu/tess/prepare.ts): triVerts, triEdges, triPatternFrame, edgeVerts,
//              edgeOwner, vertexOwner; the Catmull-Clark tables
//   cageBuf    TESS_CAGE: cage positions then vertex normals, 3 f32 each (rewritten when the
//              cage moves); with the Catmull-Clark surface then its control points and limits
//   work       TESS_WORK: per-edge and per-triangle counts at every budget candidate, the chosen
//              one's prefix sums, the planned rows, and the budget state (BUDGET_* words at
//              params.offBudget)
// Each array's offset is the Params field `off` + its name.

// PHONG_ALPHA comes with the prelude (src/gpu/contract/constants.ts).

// The plan and emit passes run once the budget accepted counts that fit.
fn emitEnabled() -> bool {
  return work[params.offBudget + BUDGET_ACCEPTED] == 1u && work[params.offBudget + BUDGET_FITS] == 1u;
}

// The thread of a WORKGROUP_SIZE-wide dispatch folded into 2D (src/gpu/tess/tessellator.ts grid2d).
fn flatIndex(wid: vec3<u32>, lid: u32) -> u32 {
  return (wid.y * GRID_X + wid.x) * WORKGROUP_SIZE + lid;
}

// The last i in [0, n − 1] whose exclusive prefix sum work[sums + i] is ≤ x: the element (cage
// edge or triangle) that output item x belongs to. Empty elements share their successor's sum,
// so the last one wins, which is the one x lies in.
fn lastAtMost(sums: u32, n: u32, x: u32) -> u32 {
  var lo = 0u;
  var hi = n - 1u;
  for (var guard = 0u; guard < 32u && lo < hi; guard++) {
    let mid = (lo + hi + 1u) >> 1u;
    if (work[sums + mid] <= x) { lo = mid; } else { hi = mid - 1u; }
  }
  return lo;
}

// ---- pattern tables (src/pattern/tables.ts; the header's offsets count from the tables' start)
fn tblSlotsOff() -> u32 { return params.offTables + tableHeader_slotsOffset(); }
fn tblStateStartOff() -> u32 { return params.offTables + tableHeader_stateStartOffset(); }
fn tblStateIndexOff() -> u32 { return params.offTables + tableHeader_stateIndexOffset(); }
fn tblStateListOff() -> u32 { return params.offTables + tableHeader_stateListOffset(); }
fn tblStateCount() -> u32 { return tableHeader_stateCount(); }

// The line state that holds at 16.16 factor F: the last state whose start is ≤ F.
fn lineState(F: u32) -> u32 {
  var lo = 0u;
  var hi = tblStateCount() - 1u;
  let off = tblStateStartOff();
  for (var guard = 0u; guard < 16u && lo < hi; guard++) {
    let mid = (lo + hi + 1u) >> 1u;
    if (staticBuf[off + mid] <= F) { lo = mid; } else { hi = mid - 1u; }
  }
  return lo;
}

// An edge of factor f0 (before the budget: wgsl/tess/factors.wgsl edgeFactor) at budget
// candidate c (contract/tess.ts BUDGET_SCALES; its last, 0, is factor 1 everywhere): its 16.16
// factor, line state and segments. The count pass counts with it at every candidate, and the
// scan's last pass stores it at the chosen one, from the same f0 bits: the same values.
fn edgeAtCandidate(f0: f32, c: u32) -> vec3<u32> {
  var f = f0 * BUDGET_SCALES[c];
  if (c == BUDGET_CANDIDATES - 1u) { f = 1.0; }
  // NaN and everything ≤ 1 become 1: nothing else reaches the tessellator.
  f = select(1.0, min(f, f32(params.maxFactor)), f >= 1.0);
  let F = clamp(u32(round(f * 65536.0)), ONE, params.maxFactor * ONE);
  let s = lineState(F);
  return vec3<u32>(F, s, statePointCount(s) - 1u);
}

// Points of a line in state s (segments = points − 1).
fn statePointCount(s: u32) -> u32 { return staticBuf[tblStateIndexOff() + 2u * s + 1u]; }

// Position of point k (canonical order) of a line in state s at factor F, exactly as
// hable-line.ts slotPosition: x0 ± ceil(|x1 − x0| · clamp(F − f0, 0, w) / w), all in u32.
fn linePoint(s: u32, F: u32, k: u32) -> u32 {
  let slot = staticBuf[tblStateListOff() + staticBuf[tblStateIndexOff() + 2u * s] + k];
  let o = tblSlotsOff() + 5u * slot;
  let x0 = staticBuf[o];
  let x1 = staticBuf[o + 1u];
  let f0 = staticBuf[o + 2u];
  let w = staticBuf[o + 3u];
  let t = min(max(F, f0) - f0, w);
  let up = x1 >= x0;
  let span = select(x0 - x1, x1 - x0, up);
  let d = (span * t + w - 1u) / w;
  return select(x0 - d, x0 + d, up);
}

// Point i of a line in the pattern frame: flipped frames read the line backwards as ONE − x.
// (One call of linePoint, not one per branch: a compiler that inlines every call builds it once.)
fn framedPoint(s: u32, F: u32, n: u32, flip: bool, i: u32) -> u32 {
  let x = linePoint(s, F, select(i, n - i, flip));
  return select(x, ONE - x, flip);
}

// ---- mesh topology ---------------------------------------------------------------------
fn triVert(t: u32, i: u32) -> u32 { return staticBuf[params.offTriVerts + 3u * t + i]; }
fn triEdge(t: u32, i: u32) -> u32 { return staticBuf[params.offTriEdges + 3u * t + i]; }
fn triPatternFrame(t: u32) -> u32 { return staticBuf[params.offTriPatternFrame + t]; }
fn edgeVert(e: u32, i: u32) -> u32 { return staticBuf[params.offEdgeVerts + 2u * e + i]; }
// Split normals at infinitely sharp creases (src/gpu/tess/prepare.ts splitCreases): the output vertex
// of triangle t's corner i (triVert(t, i) where nothing splits), and whether edge e's points are
// output once per side (the owner's first, then its twin's).
fn cornerSlot(t: u32, i: u32) -> u32 { return staticBuf[params.offCornerSlot + 3u * t + i]; }
fn edgeSplit(e: u32) -> bool { return staticBuf[params.offEdgeSplit + e] != 0u; }

// Per-edge results of the count pass at the budget's chosen candidate: lane 0 of the edge arrays
// (contract/tess.ts TESS_WORK), where the scan's last pass copies the chosen lane.
fn edgeF(e: u32) -> u32 { return work[params.offEdgeF + e]; }
fn edgeState(e: u32) -> u32 { return work[params.offEdgeState + e]; }
fn edgeSegments(e: u32) -> u32 { return work[params.offEdgeSegs + e]; }

// A triangle's pattern frame (src/pattern/clamped.ts PatternFrame): which corners play A, B, C,
// which edges play bottom, left, right and whether each runs against its edge; mirrored or not.
struct PatternFrame {
  a: u32, b: u32, c: u32,
  bottom: u32, left: u32, right: u32,
  flipBottom: bool, flipLeft: bool, flipRight: bool,
  mirrored: bool,
}

// A PatternFrameWord (src/gpu/tess/prepare.ts packPatternFrame), through the contract's getters.
fn unpackPatternFrame(w: u32) -> PatternFrame {
  return PatternFrame(patternFrameWord_a(w), patternFrameWord_b(w), patternFrameWord_c(w),
                      patternFrameWord_bottomEdge(w), patternFrameWord_leftEdge(w), patternFrameWord_rightEdge(w),
                      patternFrameWord_flipBottom(w) == 1u, patternFrameWord_flipLeft(w) == 1u,
                      patternFrameWord_flipRight(w) == 1u, patternFrameWord_mirrored(w) == 1u);
}

// ---- the surface -------------------------------------------------------------------------
// `fn evalSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint` comes from the surface module
// (wgsl/surface/phong.wgsl, or the Catmull-Clark one), appended after this file.
fn cageVec3(o: u32) -> vec3<f32> { return vec3<f32>(cageBuf[o], cageBuf[o + 1u], cageBuf[o + 2u]); }
fn cagePos(v: u32) -> vec3<f32> { return cageVec3(3u * v); }
fn cageNormal(v: u32) -> vec3<f32> { return cageVec3(params.offNormals + 3u * v); }
// The Phong surface's α of triangle t's edge i (corner i to i + 1; src/gpu/surface/phong.ts phongTriAlphas).
fn phongAlpha(t: u32, i: u32) -> f32 { return cageBuf[params.offPhongAlpha + 3u * t + i]; }

// What the factor rule reads: the cage itself (Phong), or the limit positions and normals of the
// cage vertices (Catmull-Clark, written by wgsl/cc/build.wgsl).
fn factorPos(v: u32) -> vec3<f32> { return cageVec3(params.offFactorPos + 3u * v); }
fn factorNormal(v: u32) -> vec3<f32> { return cageVec3(params.offFactorNormal + 3u * v); }

// A point of the surface, its unit normal, and its tangents along the triangle's weights
// (du = ∂P/∂w1, dv = ∂P/∂w2, w0 = 1 − w1 − w2 moving with them), which the displacement pairs
// with the uv's derivatives along the same weights (wgsl/tess/displace.wgsl).
struct SurfacePoint { pos: vec3<f32>, normal: vec3<f32>, du: vec3<f32>, dv: vec3<f32> }

// A BaryWord (src/gpu/contract/tess.ts): (w1, w2) in 16 bits each; a corner of the source triangle
// is stored as a sentinel whose fields would sum past 2^16.
fn packBary(w: vec3<u32>) -> u32 {
  if (w.y == ONE) { return BARY_CORNER1; }
  if (w.z == ONE) { return BARY_CORNER2; }
  return baryWord_pack(w.y, w.z);
}

// Barycentric weights (corner order of the triangle) from pattern-frame weights (w_A, w_B, w_C).
fn patternToCorners(f: PatternFrame, wa: u32, wb: u32, wc: u32) -> vec3<u32> {
  var w = vec3<u32>(0u);
  w[f.a] = wa;
  w[f.b] = wb;
  w[f.c] = wc;
  return w;
}
