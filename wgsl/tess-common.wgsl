// Shared by every tessellation pass. `struct Params` is generated from src/gpu/tessellator.ts
// (one definition for both sides) and prepended to this file.
//
// Buffers (few, so no pass needs more than 8 storage bindings):
//   staticBuf  the baked pattern tables (src/pattern/tables.ts layout) followed by the mesh's
//              topology (src/gpu/prepare.ts): triVerts, triEdges, triFrame, edgeVerts,
//              edgeOwner, vertexOwner at the offsets in Params
//   cageBuf    cage positions then vertex normals, 3 f32 each (may change every frame); with
//              the Catmull-Clark surface then its control points and the cage vertices' limits
//   work       per-edge and per-triangle counts, their prefix sums, and the budget state

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> staticBuf: array<u32>;
@group(0) @binding(2) var<storage, read> cageBuf: array<f32>;
@group(0) @binding(3) var<storage, read_write> work: array<u32>;

const ONE: u32 = 65536u;
const PHONG_ALPHA: f32 = 0.75;
const NO_OWNER: u32 = 0xffffffffu;
const GRID_X: u32 = 65535u; // dispatches wider than this are folded into y

// Budget state words (at params.offBudget).
const BUDGET_ACCEPTED: u32 = 0u;
const BUDGET_ATTEMPT: u32 = 1u;
const BUDGET_SCALE: u32 = 2u;
const BUDGET_FITS: u32 = 3u;

// The plan and emit passes run once the budget accepted counts that fit.
fn emitEnabled() -> bool {
  return work[params.offBudget + BUDGET_ACCEPTED] == 1u && work[params.offBudget + BUDGET_FITS] == 1u;
}

fn flatIndex(wid: vec3<u32>, lid: u32, size: u32) -> u32 {
  return (wid.y * GRID_X + wid.x) * size + lid;
}

// ---- pattern tables (header word indices as documented in src/pattern/tables.ts) ----------
fn tblSlotsOff() -> u32 { return staticBuf[5]; }
fn tblStateStartOff() -> u32 { return staticBuf[6]; }
fn tblStateIndexOff() -> u32 { return staticBuf[7]; }
fn tblStateListOff() -> u32 { return staticBuf[8]; }
fn tblMergeOff() -> u32 { return staticBuf[9]; }
fn tblMergeWords() -> u32 { return staticBuf[10]; }
fn tblStateCount() -> u32 { return staticBuf[4]; }

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
fn framedPoint(s: u32, F: u32, n: u32, flip: bool, i: u32) -> u32 {
  if (flip) { return ONE - linePoint(s, F, n - i); }
  return linePoint(s, F, i);
}

// ---- mesh topology ---------------------------------------------------------------------
fn triVert(t: u32, i: u32) -> u32 { return staticBuf[params.offTriVerts + 3u * t + i]; }
fn triEdge(t: u32, i: u32) -> u32 { return staticBuf[params.offTriEdges + 3u * t + i]; }
fn triFrame(t: u32) -> u32 { return staticBuf[params.offTriFrame + t]; }
fn edgeVert(e: u32, i: u32) -> u32 { return staticBuf[params.offEdgeVerts + 2u * e + i]; }

// Per-edge results of the factor pass.
fn edgeF(e: u32) -> u32 { return work[params.offEdgeF + e]; }
fn edgeState(e: u32) -> u32 { return work[params.offEdgeState + e]; }
fn edgeSegments(e: u32) -> u32 { return work[params.offEdgeSegs + e]; }

struct Frame {
  a: u32, b: u32, c: u32,
  bottom: u32, left: u32, right: u32,
  flipBottom: bool, flipLeft: bool, flipRight: bool,
  mirrored: bool,
}

// Unpack src/gpu/prepare.ts packFrame.
fn unpackFrame(bits: u32) -> Frame {
  return Frame(bits & 3u, (bits >> 2u) & 3u, (bits >> 4u) & 3u,
               (bits >> 6u) & 3u, (bits >> 8u) & 3u, (bits >> 10u) & 3u,
               ((bits >> 12u) & 1u) == 1u, ((bits >> 13u) & 1u) == 1u, ((bits >> 14u) & 1u) == 1u,
               ((bits >> 15u) & 1u) == 1u);
}

// ---- the surface -------------------------------------------------------------------------
// `fn evalSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint` comes from the surface module
// (wgsl/surface-phong.wgsl, or the Catmull-Clark one), appended after this file.
fn cageVec3(o: u32) -> vec3<f32> { return vec3<f32>(cageBuf[o], cageBuf[o + 1u], cageBuf[o + 2u]); }
fn cagePos(v: u32) -> vec3<f32> { return cageVec3(3u * v); }
fn cageNormal(v: u32) -> vec3<f32> { return cageVec3(params.offNormals + 3u * v); }

// What the factor rule reads: the cage itself (Phong), or the limit positions and normals of the
// cage vertices (Catmull-Clark, written by wgsl/cc-build.wgsl).
fn factorPos(v: u32) -> vec3<f32> { return cageVec3(params.offFactorPos + 3u * v); }
fn factorNormal(v: u32) -> vec3<f32> { return cageVec3(params.offFactorNormal + 3u * v); }

struct SurfacePoint { pos: vec3<f32>, normal: vec3<f32> }

// (w1, w2) in 16 bits each; a corner of the source triangle is stored as a sentinel whose
// sum exceeds 2^16 (src/gpu/types.ts).
fn packBary(w: vec3<u32>) -> u32 {
  if (w.y == ONE) { return 0xffffffffu; }
  if (w.z == ONE) { return 0xfffffffeu; }
  return w.y | (w.z << 16u);
}

// Barycentric weights (corner order of the triangle) from frame weights (w_A, w_B, w_C).
fn frameToCorners(f: Frame, wa: u32, wb: u32, wc: u32) -> vec3<u32> {
  var w = vec3<u32>(0u);
  w[f.a] = wa;
  w[f.b] = wb;
  w[f.c] = wc;
  return w;
}
