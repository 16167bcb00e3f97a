// Emit: the whole output mesh in two dispatches of one pass. The vertices: one thread per output
// vertex (indirect, sized by the budget pass), the welded vertices of the cage corners and edges
// (wgsl/tess/weld.wgsl), then the interior vertices of the cage triangles; an interior vertex
// finds its cage triangle in the prefix sums, its row in the planned rows (wgsl/tess/plan.wgsl),
// and rebuilds the few pattern values it needs from the tables. Every vertex, whatever its kind,
// is evaluated at the one call site of the surface (a shader compiler that inlines every call
// builds the exact surface's evaluator once per call site). The triangles: a workgroup per cage
// triangle (`triangles` below); their corners on cage corners and edges refer to the welded
// vertices.

fn rowKept(first: u32, j: u32) -> u32 { return work[params.offRows + 2u * (first + j)]; }
fn rowCum(first: u32, j: u32) -> u32 { return work[params.offRows + 2u * (first + j) + 1u]; }

// The last cage triangle whose prefix sum (at word offset `sums`) is ≤ x.
fn findTriangle(sums: u32, x: u32) -> u32 { return lastAtMost(sums, params.nTris, x); }

fn edgeTotal() -> u32 { return work[params.offEdgeBase + params.nEdges]; }

// The q-th interior vertex of the cage triangles, output vertex `index` (nSlots + edge points + q).
fn interiorPlace(q: u32, index: u32) -> VertexPlace {
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
  let w = patternToCorners(L.f, ONE - u - v, u, v);
  return VertexPlace(index, t, w, VERTEX_POSITION | VERTEX_SHADING, NO_OWNER, false);
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

// The output vertex of one corner of a pattern triangle, named either as a grid point (row, col)
// or as a strip point p of the gap strip (0..nI: the inner side, from the bottom edge's tail up
// the clamp line to C; then the outer side, the right edge from C back to B at p = nI + nO).
// The cases reduce in order, strip → grid → one of the three edge lines, so that each lookup
// is written once: a shader compiler that inlines every call (SwiftShader's, which CI and the
// headless runs use) then builds it once, not once per corner of each of the pass's four
// triangle forms (the per-form calls made this pass 1.4 s of a page's pipeline build).
//   grid (row, col), col clamped to the row's kept columns: row 0 is the bottom edge's line,
//     row nl the apex C, column 0 the left edge's line, anything else an interior vertex;
//   strip p ≤ tail: the bottom edge's point bottom.n − 1 − p (the tail right of the grid);
//   strip tail < p ≤ nI: the end of grid row p − tail;
//   strip p > nI: the right edge's point b = nO − (p − nI) (b = 0 is the corner B).
fn patternVertex(T: Tri, nI: u32, nO: u32, isStrip: bool, x: u32, y: u32) -> u32 {
  var line = 0u; // which edge line the point is on, when it is on one: 0 bottom, 1 left, 2 right
  var k = 0u; // its index on that line, in the line's framed direction
  var row = x;
  var col = y;
  var onGrid = !isStrip;
  if (isStrip) {
    let tail = T.L.bottom.n - 1u - T.k0;
    if (x > nI) {
      let b = nO - (x - nI);
      if (b == 0u) { return cornerSlot(T.t, T.L.f.b); }
      line = 2u;
      k = b;
    } else if (x <= tail) {
      k = T.L.bottom.n - 1u - x;
    } else {
      row = x - tail;
      col = rowKept(T.first, row);
      onGrid = true;
    }
  }
  if (onGrid) {
    let c = min(col, rowKept(T.first, row));
    if (row == 0u) {
      k = c;
    } else if (row == T.L.left.n) {
      return cornerSlot(T.t, T.L.f.c);
    } else if (c == 0u) {
      line = 1u;
      k = row;
    } else {
      return T.vertexBase + rowCum(T.first, row) - T.k0 + c - 1u;
    }
  }
  let side = select(select(T.L.f.right, T.L.f.left, line == 1u), T.L.f.bottom, line == 0u);
  let flip = select(select(T.L.f.flipRight, T.L.f.flipLeft, line == 1u), T.L.f.flipBottom, line == 0u);
  let n = select(select(T.L.right.n, T.L.left.n, line == 1u), T.L.bottom.n, line == 0u);
  return edgeVertex(T.t, triEdge(T.t, side), flip, k, n);
}

fn writeTriangle(index: u32, mirrored: bool, a: u32, b: u32, c: u32) {
  if (index >= params.triangleCapacity) { return; }
  outIndices[3u * index] = a;
  outIndices[3u * index + 1u] = select(b, c, mirrored);
  outIndices[3u * index + 2u] = select(c, b, mirrored);
}

// Output triangle `local` of cage triangle T.t (r = its index in the whole mesh).
fn emitTriangle(T: Tri, local: u32, r: u32) {
  let t = T.t;
  let L = T.L;
  let first = T.first;
  let nl = L.left.n;
  let grid = 2u * rowCum(first, nl) - T.k0; // grid triangles: 2·S_nl + k_nl − k_0, k_nl = 0
  let tail = L.bottom.n - 1u - T.k0;
  let nI = tail + nl;
  let nO = L.right.n;
  // The triangle's three corners as patternVertex names them (x, y), then one lookup each.
  var isStrip = true;
  var xs = vec3<u32>(0u);
  var ys = vec3<u32>(0u);
  if (local < grid) {
    var lo = 0u;
    var hi = nl - 1u;
    for (var guard = 0u; guard < 12u && lo < hi; guard++) {
      let mid = (lo + hi + 1u) >> 1u;
      if (2u * rowCum(first, mid) + rowKept(first, mid) - T.k0 <= local) { lo = mid; } else { hi = mid - 1u; }
    }
    let j = lo;
    let inStrip = local - (2u * rowCum(first, j) + rowKept(first, j) - T.k0);
    let k0 = rowKept(first, j);
    let k1 = rowKept(first, j + 1u);
    let both = min(k0, k1);
    var i = inStrip / 2u;
    var lower = (inStrip & 1u) == 0u;
    if (inStrip >= 2u * both) {
      i = both + (inStrip - 2u * both);
      lower = k0 > k1;
    }
    isStrip = false;
    if (lower) {
      xs = vec3<u32>(j, j, j + 1u);
      ys = vec3<u32>(i, i + 1u, i + 1u);
    } else {
      xs = vec3<u32>(j, j + 1u, j + 1u);
      ys = vec3<u32>(i, i + 1u, i);
    }
  } else {
    let g = local - grid;
    let mergeBase = params.offGapMoves + t * gapMoveWords();
    if (nI + nO + 1u <= STRIP_DP_VERTICES) {
      let rec = (work[mergeBase + (g >> 1u)] >> (16u * (g & 1u))) & 0xffffu;
      xs = vec3<u32>(rec & 15u, (rec >> 4u) & 15u, (rec >> 8u) & 15u);
    } else {
      var a = 0u;
      for (var m = 0u; m < (g >> 5u); m++) { a += countOneBits(work[mergeBase + m]); }
      let word = work[mergeBase + (g >> 5u)];
      a += countOneBits(word & ((1u << (g & 31u)) - 1u)); // g & 31 < 32, so the shift is defined
      let b = g - a;
      // inner move: (inner a, outer b, inner a+1); outer move: (inner a, outer b, outer b+1);
      // outer point b is strip point nI + nO − b
      let innerMove = ((word >> (g & 31u)) & 1u) == 1u;
      xs = vec3<u32>(a, nI + nO - b, select(nI + nO - b - 1u, a + 1u, innerMove));
    }
  }
  var v = vec3<u32>(0u);
  for (var c = 0u; c < 3u; c++) { v[c] = patternVertex(T, nI, nO, isStrip, xs[c], ys[c]); }
  writeTriangle(r, L.f.mirrored, v.x, v.y, v.z);
}

@compute @workgroup_size(WORKGROUP_SIZE)
fn vertices(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let i = flatIndex(wid, lid);
  let edgePoints = edgeTotal();
  let welded = params.nSlots + edgePoints;
  let all = welded + work[params.offTriVertBase + params.nTris];
  // After the vertices, a thread per extra sector slot for its position (weld.wgsl).
  if (i >= all + params.nSlots - params.nVerts || !emitEnabled()) { return; }
  var P: VertexPlace;
  if (i >= all) {
    P = extraSlotPosition(i - all);
  } else if (i < params.nSlots) {
    P = cornerPlace(i);
  } else if (i < welded) {
    P = edgePlace(i - params.nSlots);
  } else {
    P = interiorPlace(i - welded, i);
  }
  if (P.unused) {
    writeUnusedVertex(i, i); // a cage vertex no face with a surface uses
    return;
  }
  writeVertex(P);
}

// Apart from the vertices: an entry point without the surface's evaluator, so that a compiler
// which sizes every invocation's private memory by its entry point's largest path (SwiftShader
// zero-fills the exact evaluator's arrays) does not charge the triangles for it: one dispatch
// for both ran the exact surface's emit 2.2× slower there.
@compute @workgroup_size(WORKGROUP_SIZE)
fn triangles(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  // Tiled: one workgroup per cage triangle, its threads striding over the triangle's output
  // triangles (coalesced writes), so that what they share (the triangle's lines, where its rows
  // and vertices start) is found once per thread, not by a search of the whole mesh and a
  // rebuild of the lines for every output triangle (on SwiftShader: the pass 1.6 → 1.0 s on
  // bigguy at factor 32). Measured against it: a thread per 8 consecutive triangles of a flat
  // dispatch (their cage triangle found once while they share it) saved a quarter as much.
  // What a GPU may not like: a small cage at a high factor is few workgroups of long loops (a
  // cube at 128: 12 × 64 threads for 393,216 triangles); tiles of a fixed size would fix that.
  let t = wid.y * GRID_X + wid.x;
  if (t >= params.nTris || !emitEnabled()) { return; }
  let begin = work[params.offTriTriBase + t];
  let end = work[params.offTriTriBase + t + 1u];
  if (begin + lid >= end) { return; }
  let first = work[params.offTriRowBase + t];
  let T = Tri(t, triLines(t), first, rowKept(first, 0u), params.nSlots + edgeTotal() + work[params.offTriVertBase + t]);
  for (var r = begin + lid; r < end; r += WORKGROUP_SIZE) { emitTriangle(T, r - begin, r); }
}
