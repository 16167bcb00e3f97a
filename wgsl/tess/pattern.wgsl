// The clamped-parallelogram pattern of one cage triangle, read from the baked tables and the
// per-edge results of the factor pass (src/pattern/clamped.ts is the CPU original):
//   the pattern frame (prepare.ts packPatternFrame) names the bottom, left and right edges; a framed line is
//   an edge's line read in the pattern frame's direction; c is the clamp line u + v = c;
//   rows j = 0..nl: row 0 keeps k_0 = #{u_i < c} columns (nb − 1 if nr = 1; its points past
//   u_{k_0} are the gap strip's), row j ≥ 1 keeps k_j = #{u_i < c − v_j}, row nl is the corner
//   C; the gap strip is cut by the gap matching below (in the plan pass, once per triangle).
//   Shared by the count, plan and emit passes.

struct EdgeLine { state: u32, F: u32, n: u32, flip: bool }

// The count pass computes its triangle's three edges itself (wgsl/tess/count.wgsl) and sets
// them here (F, state, segments per local edge); every later pass reads the stored ones.
var<private> localEdgeLines: array<vec3<u32>, 3>;
var<private> useLocalEdges: bool = false;

fn edgeLine(t: u32, edgeIndex: u32, flip: bool) -> EdgeLine {
  if (useLocalEdges) {
    let l = localEdgeLines[edgeIndex];
    return EdgeLine(l.y, l.x, l.z, flip);
  }
  let e = triEdge(t, edgeIndex);
  return EdgeLine(edgeState(e), edgeF(e), edgeSegments(e), flip);
}

fn framed(l: EdgeLine, i: u32) -> u32 { return framedPoint(l.state, l.F, l.n, l.flip, i); }

// The larger of a line's last two segments (ONE for a single segment): clamped.ts endGap.
fn endGap(l: EdgeLine) -> u32 {
  if (l.n < 2u) { return ONE; }
  let last = framed(l, l.n - 1u);
  return max(ONE - last, last - framed(l, l.n - 2u));
}

// Columns of the bottom line (indices 0..nb−1) strictly left of e: binary search.
fn keptColumns(bottom: EdgeLine, e: u32) -> u32 {
  var lo = 0u;
  var hi = bottom.n; // answer in [0, nb]
  for (var guard = 0u; guard < 12u && lo < hi; guard++) {
    let mid = (lo + hi) >> 1u;
    if (framed(bottom, mid) < e) { lo = mid + 1u; } else { hi = mid; }
  }
  return lo;
}

struct TriLines { f: PatternFrame, bottom: EdgeLine, left: EdgeLine, right: EdgeLine, c: u32 }

fn triLines(t: u32) -> TriLines {
  let f = unpackPatternFrame(triPatternFrame(t));
  let bottom = edgeLine(t, f.bottom, f.flipBottom);
  let left = edgeLine(t, f.left, f.flipLeft);
  let right = edgeLine(t, f.right, f.flipRight);
  return TriLines(f, bottom, left, right, ONE - max(endGap(bottom), endGap(left)));
}

// u of row j's end, j ≥ 1 (E_j on the clamp line).
fn rowEnd(L: TriLines, j: u32) -> u32 {
  let v = framed(L.left, j);
  return select(0u, L.c - v, L.c > v);
}

// Columns row 0 keeps in the grid (clamped.ts rowZeroKept): the bottom points before the clamp
// line and the first one at or past it; all of them but B with a single right segment when the
// strip would be too large for the exact triangulation.
fn rowZeroKept(L: TriLines) -> u32 {
  let k0 = keptColumns(L.bottom, L.c);
  let big = L.bottom.n - 1u - k0 + L.left.n + L.right.n + 1u > STRIP_DP_VERTICES;
  return select(k0, L.bottom.n - 1u, L.right.n == 1u && big);
}

// ---- the gap matching (clamped.ts gapMergeSteps, capLevel: the same integers) ----------------
// The strip between the inner chain I_0..I_nI (bottom points u_{nb−1} back to u_{k_0}, then
// E_1..E_nl = C) and the outer chain O_0..O_nO (B, right edge, C) is cut from the front edge
// I_a–O_b by greedy moves: inner (I_a, O_b, I_{a+1}) or outer (I_a, O_b, O_{b+1}). The plan pass
// makes the moves once per triangle and stores one bit each (gapMoveWords words a triangle); the
// emit pass finds move g by counting bits.

// Words of a triangle's gap strip in work's gapMoves: src/gpu/contract/tess.ts gapMoveWords, the same formula
// (the greedy's moves, a bit each, or a small strip's triangles, 16 bits each).
fn gapMoveWords() -> u32 { return max((3u * (params.maxFactor + 1u) + 31u) / 32u, (STRIP_DP_VERTICES - 2u + 1u) / 2u); }

// ---- the exact triangulation of a small strip (clamped.ts stripTriangulation, angleLevel) -----
// Strips of at most STRIP_DP_VERTICES points (I_0..I_nI = C, then O_{nO−1}..O_1, B; the constant
// comes from the contract, ≤ 16) are triangulated to the least Σ 16^angleLevel; the plan pass
// stores each triangle (i, j, m) as i | j << 4 | m << 8 in 16 bits, two to a word.

// A vector scaled to at most 8 significant bits by an arithmetic shift (clamped.ts coarse8).
fn coarse8(d: vec2<i32>) -> vec2<i32> {
  let m = u32(max(abs(d.x), abs(d.y)));
  let shift = u32(max(0, i32(32u - countLeadingZeros(m)) - 8));
  return d >> vec2<u32>(shift);
}

// angleLevel at a vertex whose sides have the coarse8 directions a and b: thresholds 180° − φ as
// 1024·tan φ (clamped.ts TAN_1024).
fn angleLevelDirs(a: vec2<i32>, b: vec2<i32>) -> u32 {
  let d = a.x * b.x + a.y * b.y;
  if (d >= 0 || all(a == vec2<i32>(0)) || all(b == vec2<i32>(0))) { return 0u; }
  let c = abs(a.x * b.y - a.y * b.x) * 1024; // < 2^27
  return select(0u, 1u, c < 591 * -d) + select(0u, 1u, c < 274 * -d) + select(0u, 1u, c < 144 * -d)
       + select(0u, 1u, c < 72 * -d) + select(0u, 1u, c < 36 * -d) + select(0u, 1u, c < 18 * -d);
}


// Point p of the strip polygon: the inner chain, then the outer chain backwards from C.
fn stripPoint(L: TriLines, tail: u32, nI: u32, nO: u32, p: u32) -> vec2<i32> {
  if (p <= nI) { return innerPoint(L, tail, p); }
  return outerPoint(L, nO - (p - nI));
}

// A vector scaled to at most 5 significant bits by an arithmetic shift (clamped.ts coarse).
fn coarse(d: vec2<i32>) -> vec2<i32> {
  let m = u32(max(abs(d.x), abs(d.y)));
  let shift = u32(max(0, i32(32u - countLeadingZeros(m)) - 5));
  return d >> vec2<u32>(shift);
}

// 0 up to 150°, then 1, 2, 3 above 150°, 165°, 175° (clamped.ts obtuseAt).
fn obtuseAt(p: vec2<i32>, q: vec2<i32>, r: vec2<i32>) -> u32 {
  let a = coarse(q - p);
  let b = coarse(r - p);
  let d = a.x * b.x + a.y * b.y;
  if (d >= 0) { return 0u; }
  let d2 = d * d; // ≤ 2^22
  let n2 = (a.x * a.x + a.y * a.y) * (b.x * b.x + b.y * b.y); // ≤ 2^22
  return select(0u, 1u, 4 * d2 > 3 * n2) + select(0u, 1u, 15 * d2 > 14 * n2) + select(0u, 1u, 131 * d2 > 130 * n2);
}

fn capLevel(p: vec2<i32>, q: vec2<i32>, r: vec2<i32>) -> u32 {
  // max(obtuseAt(p, q, r), obtuseAt(q, r, p), obtuseAt(r, p, q)) as a loop: one copy of
  // obtuseAt for a compiler that inlines every call (see gapStep).
  var pts = array<vec2<i32>, 3>(p, q, r);
  var level = 0u;
  for (var i = 0u; i < 3u; i++) { level = max(level, obtuseAt(pts[i], pts[(i + 1u) % 3u], pts[(i + 2u) % 3u])); }
  return level;
}

// Squared distance of the halved difference: ≤ 2^31, exact in u32 (clamped.ts halfDist2).
fn halfDist2(p: vec2<i32>, q: vec2<i32>) -> u32 {
  let d = (q - p) >> vec2<u32>(1u);
  return u32(d.x * d.x) + u32(d.y * d.y);
}

// tail: bottom points in the inner chain before u_{k_0}; capInnerEnd / capOuterEnd: whether the
// last three points of each chain make a cap (gapMoveOk's fan-from-C test, the same for every move).
struct Gap { L: TriLines, tail: u32, nI: u32, nO: u32, capInnerEnd: bool, capOuterEnd: bool }

// Inner point a in the frame: the bottom's tail, then the row ends E_j (E_nl = C).
fn innerPoint(L: TriLines, tail: u32, a: u32) -> vec2<i32> {
  if (a <= tail) { return vec2<i32>(i32(framed(L.bottom, L.bottom.n - 1u - a)), 0); }
  let j = a - tail;
  if (j == L.left.n) { return vec2<i32>(0, i32(ONE)); }
  return vec2<i32>(i32(rowEnd(L, j)), i32(framed(L.left, j)));
}

fn outerPoint(L: TriLines, b: u32) -> vec2<i32> {
  let v = framed(L.right, b);
  return vec2<i32>(i32(ONE - v), i32(v));
}

fn gapOf(L: TriLines, k0: u32) -> Gap {
  let tail = L.bottom.n - 1u - k0;
  let nI = tail + L.left.n;
  let nO = L.right.n;
  var capI = false;
  var capO = false;
  if (nI >= 2u) { capI = capLevel(innerPoint(L, tail, nI - 2u), innerPoint(L, tail, nI - 1u), innerPoint(L, tail, nI)) > 0u; }
  if (nO >= 2u) { capO = capLevel(outerPoint(L, nO - 2u), outerPoint(L, nO - 1u), outerPoint(L, nO)) > 0u; }
  return Gap(L, tail, nI, nO, capI, capO);
}

// clamped.ts gapMoveOk.
fn gapMoveOk(G: Gap, a: u32, b: u32, inner: bool) -> bool {
  if (inner) {
    if (a == G.nI) { return false; }
    return b == G.nO || !(a + 1u == G.nI && b + 1u < G.nO && G.capOuterEnd);
  }
  if (b == G.nO) { return false; }
  return a == G.nI || !(b + 1u == G.nO && a + 1u < G.nI && G.capInnerEnd);
}

// The chains' points around the front edge: I[k] = I_{a+k}, O[k] = O_{b+k} (k = 0..2, read only
// where they exist).
struct GapWindow { i0: vec2<i32>, i1: vec2<i32>, i2: vec2<i32>, o0: vec2<i32>, o1: vec2<i32>, o2: vec2<i32> }

// NO_LEVEL: a cap level not computed (capLevel is at most 3).
const NO_LEVEL: u32 = 99u;

// One decision and what the next one can reuse: capLevel depends only on the three points, so
// the triangles the look-ahead judged are the next step's two moves (NO_LEVEL where it did not).
struct GapStep { inner: bool, nextLi: u32, nextLo: u32 }

// clamped.ts gapStepInner on the window: advance the inner chain from front edge I_a–O_b? The
// least cap level of the allowed moves at (a + 1, b) and (a, b + 1) is clamped.ts bestLevel.
// li, lo: the cap levels of this step's inner and outer move if the last step computed them.
// The six candidate triangles' corners in the window [i0, i1, i2, o0, o1, o2], three 3-bit
// indices each, in the order t3, t4, t5, t6 (the triangles after an inner or an outer move), li, lo
// (the two triangles of this move): (i1 o0 i2), (i1 o0 o1), (i0 o1 i1), (i0 o1 o2), (i0 o0 i1), (i0 o0 o1).
const GAP_CANDIDATES = array<u32, 6>(1u | (3u << 3u) | (2u << 6u), 1u | (3u << 3u) | (4u << 6u), 0u | (4u << 3u) | (1u << 6u),
                                     0u | (4u << 3u) | (5u << 6u), 0u | (3u << 3u) | (1u << 6u), 0u | (3u << 3u) | (4u << 6u));

fn gapStep(G: Gap, a: u32, b: u32, w: GapWindow, knownLi: u32, knownLo: u32) -> GapStep {
  let okInner = gapMoveOk(G, a, b, true);
  let okOuter = gapMoveOk(G, a, b, false);
  if (!okInner) { return GapStep(false, NO_LEVEL, NO_LEVEL); }
  if (!okOuter) { return GapStep(true, NO_LEVEL, NO_LEVEL); }
  // The levels of the candidates that are needed (NO_LEVEL for the others), from one capLevel
  // in a loop rather than six calls: a shader compiler that inlines every call (SwiftShader's,
  // which CI and the headless runs use) built 18 copies of obtuseAt into the plan pass.
  var want = array<bool, 6>(gapMoveOk(G, a + 1u, b, true), gapMoveOk(G, a + 1u, b, false), gapMoveOk(G, a, b + 1u, true),
                            gapMoveOk(G, a, b + 1u, false), knownLi == NO_LEVEL, knownLo == NO_LEVEL);
  var pts = array<vec2<i32>, 6>(w.i0, w.i1, w.i2, w.o0, w.o1, w.o2);
  var level = array<u32, 6>(NO_LEVEL, NO_LEVEL, NO_LEVEL, NO_LEVEL, knownLi, knownLo);
  for (var k = 0u; k < 6u; k++) {
    if (want[k]) {
      let c = GAP_CANDIDATES[k];
      level[k] = capLevel(pts[c & 7u], pts[(c >> 3u) & 7u], pts[(c >> 6u) & 7u]);
    }
  }
  let li = level[4];
  let lo = level[5];
  let t3 = level[0];
  let t4 = level[1];
  let t5 = level[2];
  let t6 = level[3];
  let bi = min(t3, t4);
  let bo = min(t5, t6);
  let si = max(li, select(bi, 0u, bi == NO_LEVEL));
  let so = max(lo, select(bo, 0u, bo == NO_LEVEL));
  var inner: bool;
  if (si != so) {
    inner = si < so;
  } else if (li != lo) {
    inner = li < lo;
  } else {
    inner = halfDist2(w.o0, w.i1) < halfDist2(w.i0, w.o1);
  }
  if (inner) { return GapStep(true, t3, t4); }
  return GapStep(false, t5, t6);
}
