// Emit: one thread per output vertex (interior vertices of the cage triangles) and one per
// output triangle, in indirect dispatches sized by the budget pass. Each thread finds its cage
// triangle in the prefix sums, its row in the planned rows (wgsl/tess/plan.wgsl), and rebuilds the
// few pattern values it needs from the tables. Corners of the output triangles that lie on cage
// corners and edges refer to the welded vertices (wgsl/tess/weld.wgsl).

fn rowKept(first: u32, j: u32) -> u32 { return work[params.offRows + 2u * (first + j)]; }
fn rowCum(first: u32, j: u32) -> u32 { return work[params.offRows + 2u * (first + j) + 1u]; }

// The last cage triangle whose prefix sum (at word offset `sums`) is ≤ x.
fn findTriangle(sums: u32, x: u32) -> u32 { return lastAtMost(sums, params.nTris, x); }

fn edgeTotal() -> u32 { return work[params.offEdgeBase + params.nEdges]; }

@compute @workgroup_size(WORKGROUP_SIZE)
fn vertices(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let q = flatIndex(wid, lid);
  if (q >= work[params.offTriVertBase + params.nTris] || !emitEnabled()) { return; }
  let t = findTriangle(params.offTriVertBase, q);
  let local = q - work[params.offTriVertBase + t];
  let L = triLines(t);
  let first = work[params.offTriRowBase + t];
  let k0 = rowKept(first, 0u);
  // The row: the last j in [1, nl − 1] with S_j − k_0 ≤ local.
  var lo = 1u;
  var hi = L.left.n - 1u;
  for (var guard = 0u; guard < 12u && lo < hi; guard++) {
    let mid = (lo + hi + 1u) >> 1u;
    if (rowCum(first, mid) - k0 <= local) { lo = mid; } else { hi = mid - 1u; }
  }
  let j = lo;
  let col = local - (rowCum(first, j) - k0) + 1u; // columns 1..k_j; column k_j is the row end E_j
  let u = select(rowEnd(L, j), framed(L.bottom, col), col < rowKept(first, j));
  let v = framed(L.left, j);
  writeVertex(params.nSlots + edgeTotal() + q, t, patternToCorners(L.f, ONE - u - v, u, v));
}

struct Tri { t: u32, L: TriLines, first: u32, k0: u32, vertexBase: u32 }

// Triangle t's output vertex at its corner on cage vertex v (its sector's, where normals split).
fn cornerVertex(t: u32, v: u32) -> u32 {
  return cornerSlot(t, select(select(2u, 1u, triVert(t, 1u) == v), 0u, triVert(t, 0u) == v));
}

// Point framedIdx of `edge` (n segments) as triangle t sees it: where the edge's normals split,
// the twin triangle's points are the second copy.
fn edgeVertex(t: u32, edge: u32, flip: bool, framedIdx: u32, n: u32) -> u32 {
  let k = select(framedIdx, n - framedIdx, flip);
  if (k == 0u) { return cornerVertex(t, edgeVert(edge, 0u)); }
  if (k == n) { return cornerVertex(t, edgeVert(edge, 1u)); }
  let twinSide = edgeSplit(edge) && ownerWord_tri(staticBuf[params.offEdgeOwner + edge]) != t;
  return params.nSlots + work[params.offEdgeBase + edge] + k - 1u + select(0u, n - 1u, twinSide);
}

fn gridVertex(T: Tri, row: u32, col: u32) -> u32 {
  let c = min(col, rowKept(T.first, row));
  if (row == 0u) { return edgeVertex(T.t, triEdge(T.t, T.L.f.bottom), T.L.f.flipBottom, c, T.L.bottom.n); }
  if (row == T.L.left.n) { return cornerSlot(T.t, T.L.f.c); }
  if (c == 0u) { return edgeVertex(T.t, triEdge(T.t, T.L.f.left), T.L.f.flipLeft, row, T.L.left.n); }
  return T.vertexBase + rowCum(T.first, row) - T.k0 + c - 1u;
}

// Inner chain point a of the gap strip: the bottom's points u_{nb−1} back to u_{k_0}, then the
// row ends E_1..E_nl (= C).
fn innerVertex(T: Tri, a: u32) -> u32 {
  let tail = T.L.bottom.n - 1u - T.k0;
  if (a <= tail) { return edgeVertex(T.t, triEdge(T.t, T.L.f.bottom), T.L.f.flipBottom, T.L.bottom.n - 1u - a, T.L.bottom.n); }
  let j = a - tail;
  return gridVertex(T, j, rowKept(T.first, j));
}

fn outerVertex(T: Tri, b: u32) -> u32 {
  if (b == 0u) { return cornerSlot(T.t, T.L.f.b); }
  if (b == T.L.right.n) { return cornerSlot(T.t, T.L.f.c); }
  return edgeVertex(T.t, triEdge(T.t, T.L.f.right), T.L.f.flipRight, b, T.L.right.n);
}

// Point p of the strip polygon (wgsl/tess/pattern.wgsl stripPoint) as an output vertex.
fn stripVertex(T: Tri, nI: u32, nO: u32, p: u32) -> u32 {
  if (p <= nI) { return innerVertex(T, p); }
  return outerVertex(T, nO - (p - nI));
}

fn writeTriangle(index: u32, mirrored: bool, a: u32, b: u32, c: u32) {
  if (index >= params.triangleCapacity) { return; }
  outIndices[3u * index] = a;
  outIndices[3u * index + 1u] = select(b, c, mirrored);
  outIndices[3u * index + 2u] = select(c, b, mirrored);
}

@compute @workgroup_size(WORKGROUP_SIZE)
fn triangles(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let r = flatIndex(wid, lid);
  if (r >= work[params.offTriTriBase + params.nTris] || !emitEnabled()) { return; }
  let t = findTriangle(params.offTriTriBase, r);
  let local = r - work[params.offTriTriBase + t];
  let L = triLines(t);
  let first = work[params.offTriRowBase + t];
  let T = Tri(t, L, first, rowKept(first, 0u), params.nSlots + edgeTotal() + work[params.offTriVertBase + t]);
  let nl = L.left.n;
  let mirrored = L.f.mirrored;
  let grid = 2u * rowCum(first, nl) - T.k0; // grid triangles: 2·S_nl + k_nl − k_0, k_nl = 0
  if (local < grid) {
    // The row strip: the last j in [0, nl − 1] with 2·S_j + k_j − k_0 ≤ local.
    var lo = 0u;
    var hi = nl - 1u;
    for (var guard = 0u; guard < 12u && lo < hi; guard++) {
      let mid = (lo + hi + 1u) >> 1u;
      if (2u * rowCum(first, mid) + rowKept(first, mid) - T.k0 <= local) { lo = mid; } else { hi = mid - 1u; }
    }
    let j = lo;
    let inStrip = local - (2u * rowCum(first, j) + rowKept(first, j) - T.k0);
    // clamped.ts emits, for column i, a lower triangle while i < k_j and an upper one while
    // i < k_{j+1}: pairs first, then the longer row's remainder.
    let k0 = rowKept(first, j);
    let k1 = rowKept(first, j + 1u);
    let both = min(k0, k1);
    var i = inStrip / 2u;
    var lower = (inStrip & 1u) == 0u;
    if (inStrip >= 2u * both) {
      i = both + (inStrip - 2u * both);
      lower = k0 > k1;
    }
    if (lower) {
      writeTriangle(r, mirrored, gridVertex(T, j, i), gridVertex(T, j, i + 1u), gridVertex(T, j + 1u, i + 1u));
    } else {
      writeTriangle(r, mirrored, gridVertex(T, j, i), gridVertex(T, j + 1u, i + 1u), gridVertex(T, j + 1u, i));
    }
    return;
  }
  let g = local - grid;
  let mergeBase = params.offGapMoves + t * gapMoveWords();
  let tail = L.bottom.n - 1u - T.k0;
  let nI = tail + nl;
  let nO = L.right.n;
  if (nI + nO + 1u <= STRIP_DP_VERTICES) {
    // A small strip: triangle g of its exact triangulation, (i, j, m) in 16 bits (wgsl/tess/plan.wgsl).
    let rec = (work[mergeBase + (g >> 1u)] >> (16u * (g & 1u))) & 0xffffu;
    writeTriangle(r, mirrored, stripVertex(T, nI, nO, rec & 15u), stripVertex(T, nI, nO, (rec >> 4u) & 15u), stripVertex(T, nI, nO, (rec >> 8u) & 15u));
    return;
  }
  // A large strip: move g of the gap matching, as the plan pass stored it (one bit a move, 1 =
  // inner); the moves before it say where the front edge I_a–O_b is.
  var a = 0u;
  for (var m = 0u; m < (g >> 5u); m++) { a += countOneBits(work[mergeBase + m]); }
  let word = work[mergeBase + (g >> 5u)];
  a += countOneBits(word & ((1u << (g & 31u)) - 1u)); // g & 31 < 32, so the shift is defined
  let b = g - a;
  if (((word >> (g & 31u)) & 1u) == 1u) {
    writeTriangle(r, mirrored, innerVertex(T, a), outerVertex(T, b), innerVertex(T, a + 1u));
  } else {
    writeTriangle(r, mirrored, innerVertex(T, a), outerVertex(T, b), outerVertex(T, b + 1u));
  }
}
