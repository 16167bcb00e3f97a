// Pass 2 of each budget attempt, one thread per triangle: how many interior vertices and how
// many triangles its clamped-parallelogram pattern has (edge and corner vertices belong to
// the edges and corners, and are counted there). Same construction as src/pattern/clamped.ts:
//   rows j = 0..nl, row 0 keeps nb − 1 columns, row j ≥ 1 keeps k_j = #{u_i < c − v_j},
//   row nl is the corner C; interior vertices = Σ_{0<j<nl} k_j;
//   triangles = Σ_{j<nl} (k_j + k_{j+1}) + (nl + nr − 1).

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

@compute @workgroup_size(64)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let t = flatIndex(wid, lid, 64u);
  if (t >= params.nTris || work[params.offBudget + BUDGET_ACCEPTED] != 0u) { return; }
  let f = unpackFrame(triFrame(t));
  let bottom = edgeLine(t, f.bottom, f.flipBottom);
  let left = edgeLine(t, f.left, f.flipLeft);
  let right = edgeLine(t, f.right, f.flipRight);
  let c = ONE - max(endGap(bottom), endGap(left));
  var interior = 0u;
  var triangles = bottom.n - 1u; // k_0
  for (var j = 1u; j < left.n; j++) {
    let v = framed(left, j);
    let k = keptColumns(bottom, select(0u, c - v, c > v));
    interior += k;
    triangles += 2u * k;
  }
  // Σ_{j<nl}(k_j + k_{j+1}) = k_0 + 2·Σ_{0<j<nl} k_j + k_nl, with k_nl = 0.
  triangles += left.n + right.n - 1u;
  work[params.offTriVertCount + t] = interior;
  work[params.offTriTriCount + t] = triangles;
}
