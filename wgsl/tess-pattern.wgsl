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

// Compile time: shader compilers inline every call, and innerPoint/outerPoint evaluate a line
// pattern from the tables, so each is called from as few places as possible (loops over the
// two moves and the three corners instead of one call per case): with one call per case the
// emit pass took ~12 s to compile on SwiftShader. The logic is clamped.ts's, step for step.

// Point i of the inner chain (inner) or of the outer chain.
fn gapPoint(G: Gap, inner: bool, i: u32) -> vec2<i32> {
  if (inner) { return innerPoint(G, i); }
  return outerPoint(G, i);
}

// capLevel of the triangle of three chain points (chain: true = inner).
fn gapTriLevel(G: Gap, chain: vec3<bool>, idx: vec3<u32>) -> u32 {
  var p: array<vec2<i32>, 3>;
  for (var k = 0u; k < 3u; k++) { p[k] = gapPoint(G, chain[k], idx[k]); }
  return capLevel(p[0], p[1], p[2]);
}

// clamped.ts gapMoveOk: may the front edge I_a–O_b advance along the inner (or outer) chain?
fn gapMoveOk(G: Gap, a: u32, b: u32, inner: bool) -> bool {
  let x = select(b, a, inner); // the moving chain's index and count
  let nx = select(G.nO, G.nI, inner);
  let y = select(a, b, inner); // the other chain's
  let ny = select(G.nI, G.nO, inner);
  if (x == nx) { return false; }
  if (y == ny || !(x + 1u == nx && y + 1u < ny)) { return true; }
  // Not onto the moving chain's last point while the other chain's last three make a cap.
  return gapTriLevel(G, vec3<bool>(!inner), vec3<u32>(ny - 2u, ny - 1u, ny)) == 0u;
}

// The cap level of the triangle a move makes: (I_a, O_b, I_a+1) or (I_a, O_b, O_b+1).
fn moveLevel(G: Gap, a: u32, b: u32, inner: bool) -> u32 {
  return gapTriLevel(G, vec3<bool>(true, false, inner), vec3<u32>(a, b, select(b + 1u, a + 1u, inner)));
}

fn bestLevel(G: Gap, a: u32, b: u32) -> u32 {
  var best = 4u;
  for (var k = 0u; k < 2u; k++) {
    let inner = k == 0u;
    if (gapMoveOk(G, a, b, inner)) { best = min(best, moveLevel(G, a, b, inner)); }
  }
  return select(best, 0u, best == 4u);
}

// clamped.ts gapStepInner: advance the inner chain from front edge I_a–O_b?
fn gapStepInner(G: Gap, a: u32, b: u32) -> bool {
  var ok: array<bool, 2>; // [inner, outer]
  for (var k = 0u; k < 2u; k++) { ok[k] = gapMoveOk(G, a, b, k == 0u); }
  if (!ok[0]) { return false; }
  if (!ok[1]) { return true; }
  var level: array<u32, 2>; // the move's own cap level
  var ahead: array<u32, 2>; // and the worst of it and the best next move after it
  for (var k = 0u; k < 2u; k++) {
    let inner = k == 0u;
    level[k] = moveLevel(G, a, b, inner);
    ahead[k] = max(level[k], bestLevel(G, a + select(0u, 1u, inner), b + select(1u, 0u, inner)));
  }
  if (ahead[0] != ahead[1]) { return ahead[0] < ahead[1]; }
  if (level[0] != level[1]) { return level[0] < level[1]; }
  // Ties: the shorter diagonal, O_b–I_a+1 (inner) against I_a–O_b+1 (outer).
  var d: array<u32, 2>;
  for (var k = 0u; k < 2u; k++) {
    let inner = k == 0u;
    d[k] = halfDist2(gapPoint(G, !inner, select(a, b, inner)), gapPoint(G, inner, select(b + 1u, a + 1u, inner)));
  }
  return d[0] < d[1];
}
