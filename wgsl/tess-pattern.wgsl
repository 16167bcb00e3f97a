// The clamped-parallelogram pattern of one cage triangle, read from the baked tables and the
// per-edge results of the factor pass (src/pattern/clamped.ts is the CPU original):
//   the frame (prepare.ts packFrame) names the bottom, left and right edges; a framed line is
//   an edge's line read in the frame's direction; c is the clamp line u + v = c;
//   rows j = 0..nl: row 0 keeps k_0 = #{u_i < c} columns (nb − 1 if nr = 1; the points past u_{k_0} are the gap
//   strip's), row j ≥ 1 keeps k_j = #{u_i < c − v_j}, row nl is the corner C; the gap strip is
//   cut by the gap matching below. Shared by the count, plan and emit passes.

struct EdgeLine { state: u32, F: u32, n: u32, flip: bool }

fn edgeLine(t: u32, edgeIndex: u32, flip: bool) -> EdgeLine {
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

struct TriLines { f: Frame, bottom: EdgeLine, left: EdgeLine, right: EdgeLine, c: u32 }

fn triLines(t: u32) -> TriLines {
  let f = unpackFrame(triFrame(t));
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

// ---- the gap matching (clamped.ts gapMergeSteps, capLevel: the same integers) ----------------
// The strip between the inner chain I_0..I_nI (bottom points u_{nb−1} back to u_{k_0}, then
// E_1..E_nl = C) and the outer chain O_0..O_nO (B, right edge, C) is cut from the front edge
// I_a–O_b by greedy moves: inner (I_a, O_b, I_{a+1}) or outer (I_a, O_b, O_{b+1}).

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
  return max(obtuseAt(p, q, r), max(obtuseAt(q, r, p), obtuseAt(r, p, q)));
}

// Squared distance of the halved difference: ≤ 2^31, exact in u32 (clamped.ts halfDist2).
fn halfDist2(p: vec2<i32>, q: vec2<i32>) -> u32 {
  let d = (q - p) >> vec2<u32>(1u);
  return u32(d.x * d.x) + u32(d.y * d.y);
}

struct Gap { L: TriLines, k0: u32, tail: u32, nI: u32, nO: u32 }

fn gapOf(L: TriLines, k0: u32) -> Gap {
  let tail = L.bottom.n - 1u - k0;
  return Gap(L, k0, tail, tail + L.left.n, L.right.n);
}

// Inner point a in the frame: the bottom's tail, then the row ends E_j (E_nl = C).
fn innerPoint(G: Gap, a: u32) -> vec2<i32> {
  if (a <= G.tail) { return vec2<i32>(i32(framed(G.L.bottom, G.L.bottom.n - 1u - a)), 0); }
  let j = a - G.tail;
  if (j == G.L.left.n) { return vec2<i32>(0, i32(ONE)); }
  return vec2<i32>(i32(rowEnd(G.L, j)), i32(framed(G.L.left, j)));
}

fn outerPoint(G: Gap, b: u32) -> vec2<i32> {
  let v = framed(G.L.right, b);
  return vec2<i32>(i32(ONE - v), i32(v));
}

// clamped.ts gapMoveOk.
fn gapMoveOk(G: Gap, a: u32, b: u32, inner: bool) -> bool {
  if (inner) {
    if (a == G.nI) { return false; }
    if (b == G.nO || !(a + 1u == G.nI && b + 1u < G.nO)) { return true; }
    return capLevel(outerPoint(G, G.nO - 2u), outerPoint(G, G.nO - 1u), outerPoint(G, G.nO)) == 0u;
  }
  if (b == G.nO) { return false; }
  if (a == G.nI || !(b + 1u == G.nO && a + 1u < G.nI)) { return true; }
  return capLevel(innerPoint(G, G.nI - 2u), innerPoint(G, G.nI - 1u), innerPoint(G, G.nI)) == 0u;
}

fn moveLevel(G: Gap, a: u32, b: u32, inner: bool) -> u32 {
  if (inner) { return capLevel(innerPoint(G, a), outerPoint(G, b), innerPoint(G, a + 1u)); }
  return capLevel(innerPoint(G, a), outerPoint(G, b), outerPoint(G, b + 1u));
}

fn bestLevel(G: Gap, a: u32, b: u32) -> u32 {
  var best = 4u;
  if (gapMoveOk(G, a, b, true)) { best = min(best, moveLevel(G, a, b, true)); }
  if (gapMoveOk(G, a, b, false)) { best = min(best, moveLevel(G, a, b, false)); }
  return select(best, 0u, best == 4u);
}

// clamped.ts gapStepInner: advance the inner chain from front edge I_a–O_b?
fn gapStepInner(G: Gap, a: u32, b: u32) -> bool {
  let okInner = gapMoveOk(G, a, b, true);
  let okOuter = gapMoveOk(G, a, b, false);
  if (!okInner) { return false; }
  if (!okOuter) { return true; }
  let li = moveLevel(G, a, b, true);
  let lo = moveLevel(G, a, b, false);
  let si = max(li, bestLevel(G, a + 1u, b));
  let so = max(lo, bestLevel(G, a, b + 1u));
  if (si != so) { return si < so; }
  if (li != lo) { return li < lo; }
  return halfDist2(outerPoint(G, b), innerPoint(G, a + 1u)) < halfDist2(innerPoint(G, a), outerPoint(G, b + 1u));
}
