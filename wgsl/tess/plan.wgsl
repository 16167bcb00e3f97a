// Plan, once the budget has accepted the counts: one thread per cage triangle writes its
// pattern's rows (rows 0..nl at the triangle's row offset from the prefix sums), two words each:
//   k_j  the columns the row keeps (row 0: #{u_i < c}, or nb − 1 with a single right segment;
//        row nl, the corner C: 0)
//   S_j  Σ_{j'<j} k_j', from which the emit passes find a row by binary search:
//        interior vertices before row j (j ≥ 1) = S_j − k_0,
//        grid triangles before row strip j     = 2·S_j + k_j − k_0.
// and the gap matching's moves (wgsl/tess/pattern.wgsl gapStep), one bit each (1: the inner
// chain advances), gapMoveWords words from t · gapMoveWords() in work's gapMoves. The moves
// depend on all the strip's points, so they are made here once per cage triangle and not
// replayed by every output triangle. With the rows and moves planned, every output vertex and
// triangle is written by its own thread (emit): no workgroup memory and no barriers, so the work
// is spread evenly whatever the factors.

// clamped.ts stripTriangulation: the interval recursion over the polygon's points (best cost and
// split of each interval, n ≤ STRIP_DP_VERTICES ≤ 16), then its triangles in the order of a
// depth-first walk.
fn planSmallStrip(L: TriLines, G: Gap, n: u32, base: u32) {
  var pts: array<vec2<i32>, STRIP_DP_VERTICES>;
  for (var p = 0u; p < n; p++) { pts[p] = stripPoint(L, G.tail, G.nI, G.nO, p); }
  // The coarse direction from every point to every other (clamped.ts angleLevel takes them
  // from the same differences), so each triple only compares them.
  var dirs: array<vec2<i32>, STRIP_DP_VERTICES * STRIP_DP_VERTICES>;
  for (var a = 0u; a < n; a++) {
    for (var b = 0u; b < n; b++) { dirs[a * n + b] = coarse8(pts[b] - pts[a]); }
  }
  var cost: array<u32, STRIP_DP_VERTICES * STRIP_DP_VERTICES>;
  var split: array<u32, STRIP_DP_VERTICES * STRIP_DP_VERTICES>;
  for (var i = 0u; i + 1u < n; i++) { cost[i * n + i + 1u] = 0u; }
  for (var len = 2u; len < n; len++) {
    for (var i = 0u; i + len < n; i++) {
      let j = i + len;
      var best = 0xffffffffu;
      for (var m = i + 1u; m < j; m++) {
        // 16^level ≤ 2^24, and at most 14 triangles (n ≤ 16): no overflow.
        let level = max(angleLevelDirs(dirs[i * n + j], dirs[i * n + m]),
                        max(angleLevelDirs(dirs[j * n + m], dirs[j * n + i]), angleLevelDirs(dirs[m * n + i], dirs[m * n + j])));
        let c = cost[i * n + m] + cost[m * n + j] + (1u << (4u * level));
        if (c < best) {
          best = c;
          split[i * n + j] = m;
        }
      }
      cost[i * n + j] = best;
    }
  }
  // Depth-first from (0, n − 1), lower half first: a stack of intervals, at most n deep.
  var stack: array<u32, STRIP_DP_VERTICES>;
  stack[0] = n - 1u; // (i << 8) | j with i = 0
  var top = 1u;
  var g = 0u;
  var word = 0u;
  while (top > 0u) {
    top--;
    let i = stack[top] >> 8u;
    let j = stack[top] & 0xffu;
    if (j - i < 2u) { continue; }
    let m = split[i * n + j];
    word |= (i | (j << 4u) | (m << 8u)) << (16u * (g & 1u));
    if ((g & 1u) == 1u) {
      work[base + (g >> 1u)] = word;
      word = 0u;
    }
    g++;
    stack[top] = (m << 8u) | j;
    stack[top + 1u] = (i << 8u) | m;
    top += 2u;
  }
  if ((g & 1u) == 1u) { work[base + (g >> 1u)] = word; }
}

@compute @workgroup_size(WORKGROUP_SIZE)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let t = flatIndex(wid, lid);
  if (t >= params.nTris || !emitEnabled()) { return; }
  let L = triLines(t);
  let first = work[params.offTriRowBase + t];
  let k0 = rowZeroKept(L);
  var cum = 0u;
  for (var j = 0u; j <= L.left.n; j++) {
    var k = 0u;
    if (j == 0u) { k = k0; } else if (j < L.left.n) { k = keptColumns(L.bottom, rowEnd(L, j)); }
    let o = params.offRows + 2u * (first + j);
    work[o] = k;
    work[o + 1u] = cum;
    cum += k;
  }

  let G = gapOf(L, k0);
  let base = params.offGapMoves + t * gapMoveWords();
  let n = G.nI + G.nO + 1u; // the strip polygon's points
  if (n <= STRIP_DP_VERTICES) {
    planSmallStrip(L, G, n, base);
    return;
  }
  // The gap matching, on a sliding window of the chains' points (each point read once).
  var w = GapWindow(innerPoint(L, G.tail, 0u), innerPoint(L, G.tail, min(1u, G.nI)), innerPoint(L, G.tail, min(2u, G.nI)),
                    outerPoint(L, 0u), outerPoint(L, min(1u, G.nO)), outerPoint(L, min(2u, G.nO)));
  var a = 0u;
  var b = 0u;
  let moves = G.nI + G.nO - 1u; // the last move closes at C and is never emitted
  var word = 0u;
  var knownLi = NO_LEVEL;
  var knownLo = NO_LEVEL;
  for (var m = 0u; m < moves; m++) {
    let step = gapStep(G, a, b, w, knownLi, knownLo);
    knownLi = step.nextLi;
    knownLo = step.nextLo;
    if (step.inner) {
      word |= 1u << (m & 31u);
      a++;
      w.i0 = w.i1;
      w.i1 = w.i2;
      w.i2 = innerPoint(L, G.tail, min(a + 2u, G.nI));
    } else {
      b++;
      w.o0 = w.o1;
      w.o1 = w.o2;
      w.o2 = outerPoint(L, min(b + 2u, G.nO));
    }
    if ((m & 31u) == 31u) {
      work[base + (m >> 5u)] = word;
      word = 0u;
    }
  }
  if ((moves & 31u) != 0u) { work[base + (moves >> 5u)] = word; }
}
