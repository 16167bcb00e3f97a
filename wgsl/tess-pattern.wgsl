// The clamped-parallelogram pattern of one cage triangle, read from the baked tables and the
// per-edge results of the factor pass (src/pattern/clamped.ts is the CPU original):
//   the pattern frame (prepare.ts packPatternFrame) names the bottom, left and right edges; a framed line is
//   an edge's line read in the pattern frame's direction; c is the clamp line u + v = c;
//   rows j = 0..nl: row 0 keeps nb − 1 columns, row j ≥ 1 keeps k_j = #{u_i < c − v_j}, row nl
//   is the corner C. Shared by the count, plan and emit passes.

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

struct TriLines { f: PatternFrame, bottom: EdgeLine, left: EdgeLine, right: EdgeLine, c: u32 }

fn triLines(t: u32) -> TriLines {
  let f = unpackPatternFrame(triPatternFrame(t));
  let bottom = edgeLine(t, f.bottom, f.flipBottom);
  let left = edgeLine(t, f.left, f.flipLeft);
  let right = edgeLine(t, f.right, f.flipRight);
  return TriLines(f, bottom, left, right, ONE - max(endGap(bottom), endGap(left)));
}

// u of row j's end (E_j on the clamp line; for row 0, the bottom point P = u_{nb−1}).
fn rowEnd(L: TriLines, j: u32) -> u32 {
  if (j == 0u) { return framed(L.bottom, L.bottom.n - 1u); }
  let v = framed(L.left, j);
  return select(0u, L.c - v, L.c > v);
}
