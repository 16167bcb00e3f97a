// The tessellation proper: one workgroup per cage triangle rebuilds its clamped-parallelogram
// pattern (src/pattern/clamped.ts, from the baked tables) in workgroup memory, then its 64
// threads write the triangle's interior vertices (surface evaluated in the same pass) and all
// of its triangles, whose corners on edges and cage corners refer to the welded vertices.

@group(0) @binding(8) var<storage, read_write> outIndices: array<u32>;

const MAX_POINTS: u32 = 257u; // a line has at most maxFactor + 1 ≤ 257 points
const MAX_ROWS: u32 = 258u;

struct TriInfo {
  go: u32,
  t: u32,
  frame: u32,
  bottomEdge: u32, leftEdge: u32, rightEdge: u32,
  nb: u32, nl: u32, nr: u32,
  cornerB: u32, cornerC: u32,
  vertexBase: u32,   // first interior vertex of this triangle
  triangleBase: u32, // first output triangle of this triangle
  gridTriangles: u32,
  triangles: u32,
  interior: u32,
  mergeBase: u32,    // first word of the gap-matching record
}

var<workgroup> info: TriInfo;
var<workgroup> sGo: u32;
var<workgroup> sBottom: array<u32, MAX_POINTS>;  // framed bottom line u_0..u_nb
var<workgroup> sLeft: array<u32, MAX_POINTS>;    // framed left line v_0..v_nl
var<workgroup> sKept: array<u32, MAX_ROWS>;      // k_j, columns kept in row j (row 0: nb − 1)
var<workgroup> sEnd: array<u32, MAX_ROWS>;       // u of the row's last vertex (E_j; row 0: P)
var<workgroup> sVertBase: array<u32, MAX_ROWS>;  // interior vertices before row j (rows 1..nl)
var<workgroup> sTriBase: array<u32, MAX_ROWS>;   // grid triangles before row strip j
var<workgroup> sMergePop: array<u32, 20>;        // inner-chain steps before merge word m

fn edgeVertex(edge: u32, flip: bool, framedIdx: u32, n: u32) -> u32 {
  let k = select(framedIdx, n - framedIdx, flip);
  if (k == 0u) { return edgeVert(edge, 0u); }
  if (k == n) { return edgeVert(edge, 1u); }
  return params.nVerts + work[params.offEdgeBase + edge] + k - 1u;
}

fn gridVertex(f: Frame, row: u32, col: u32) -> u32 {
  let c = min(col, sKept[row]);
  if (row == 0u) { return edgeVertex(info.bottomEdge, f.flipBottom, c, info.nb); }
  if (row == info.nl) { return info.cornerC; }
  if (c == 0u) { return edgeVertex(info.leftEdge, f.flipLeft, row, info.nl); }
  return info.vertexBase + sVertBase[row] + c - 1u;
}

fn innerVertex(f: Frame, a: u32) -> u32 { return gridVertex(f, a, sKept[a]); }

fn outerVertex(f: Frame, b: u32) -> u32 {
  if (b == 0u) { return info.cornerB; }
  if (b == info.nr) { return info.cornerC; }
  return edgeVertex(info.rightEdge, f.flipRight, b, info.nr);
}

fn mergeBit(g: u32) -> bool { return ((staticBuf[info.mergeBase + (g >> 5u)] >> (g & 31u)) & 1u) == 1u; }

fn innerStepsBefore(g: u32) -> u32 {
  let word = staticBuf[info.mergeBase + (g >> 5u)];
  let mask = select((1u << (g & 31u)) - 1u, 0u, (g & 31u) == 0u);
  return sMergePop[g >> 5u] + countOneBits(word & mask);
}

fn writeTriangle(index: u32, f: Frame, a: u32, b: u32, c: u32) {
  if (index >= params.triangleCapacity) { return; }
  outIndices[3u * index] = a;
  outIndices[3u * index + 1u] = select(b, c, f.mirrored);
  outIndices[3u * index + 2u] = select(c, b, f.mirrored);
}

// Binary search: the last index j in [lo, hi] with table[j] ≤ x.
fn lastAtMost(useTri: bool, lo0: u32, hi0: u32, x: u32) -> u32 {
  var lo = lo0;
  var hi = hi0;
  for (var guard = 0u; guard < 12u && lo < hi; guard++) {
    let mid = (lo + hi + 1u) >> 1u;
    let v = select(sVertBase[mid], sTriBase[mid], useTri);
    if (v <= x) { lo = mid; } else { hi = mid - 1u; }
  }
  return lo;
}

@compute @workgroup_size(64)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let t = wid.y * GRID_X + wid.x;
  if (lid == 0u) {
    sGo = select(0u, 1u, t < params.nTris && emitEnabled());
  }
  if (workgroupUniformLoad(&sGo) == 0u) { return; }

  let f = unpackFrame(triFrame(t));
  if (lid == 0u) {
    let be = triEdge(t, f.bottom);
    let le = triEdge(t, f.left);
    let re = triEdge(t, f.right);
    info.t = t;
    info.bottomEdge = be;
    info.leftEdge = le;
    info.rightEdge = re;
    info.nb = edgeSegments(be);
    info.nl = edgeSegments(le);
    info.nr = edgeSegments(re);
    info.cornerB = triVert(t, f.b);
    info.cornerC = triVert(t, f.c);
    info.vertexBase = params.nVerts + work[params.offEdgeBase + params.nEdges] + work[params.offTriVertBase + t];
    info.triangleBase = work[params.offTriTriBase + t];
    let record = ((edgeState(le) * tblStateCount() + edgeState(re)) * 2u + select(0u, 1u, f.flipLeft)) * 2u + select(0u, 1u, f.flipRight);
    info.mergeBase = tblMergeOff() + record * tblMergeWords();
  }
  workgroupBarrier();

  // The framed bottom and left lines.
  let bs = edgeState(info.bottomEdge);
  let bF = edgeF(info.bottomEdge);
  let ls = edgeState(info.leftEdge);
  let lF = edgeF(info.leftEdge);
  for (var i = lid; i <= info.nb; i += 64u) { sBottom[i] = framedPoint(bs, bF, info.nb, f.flipBottom, i); }
  for (var i = lid; i <= info.nl; i += 64u) { sLeft[i] = framedPoint(ls, lF, info.nl, f.flipLeft, i); }
  workgroupBarrier();

  // The clamp line u + v = c, c = 1 − the larger end gap of the two lines (clamped.ts endGap).
  let nb = info.nb;
  let nl = info.nl;
  var gapB = ONE;
  if (nb >= 2u) { gapB = max(ONE - sBottom[nb - 1u], sBottom[nb - 1u] - sBottom[nb - 2u]); }
  var gapL = ONE;
  if (nl >= 2u) { gapL = max(ONE - sLeft[nl - 1u], sLeft[nl - 1u] - sLeft[nl - 2u]); }
  let c = ONE - max(gapB, gapL);

  // Rows: kept columns and row ends.
  for (var j = lid; j <= nl; j += 64u) {
    if (j == 0u) {
      sKept[0] = nb - 1u;
      sEnd[0] = sBottom[nb - 1u];
    } else {
      let v = sLeft[j];
      let e = select(0u, c - v, c > v);
      var lo = 0u;
      var hi = nb;
      for (var guard = 0u; guard < 12u && lo < hi; guard++) {
        let mid = (lo + hi) >> 1u;
        if (sBottom[mid] < e) { lo = mid + 1u; } else { hi = mid; }
      }
      sKept[j] = lo;
      sEnd[j] = e;
    }
  }
  workgroupBarrier();

  if (lid == 0u) {
    var verts = 0u;
    var tris = 0u;
    for (var j = 0u; j <= nl; j++) {
      sVertBase[j] = verts;
      sTriBase[j] = tris;
      if (j >= 1u && j < nl) { verts += sKept[j]; }
      if (j < nl) { tris += sKept[j] + sKept[j + 1u]; }
    }
    info.interior = verts;
    info.gridTriangles = tris;
    info.triangles = tris + nl + info.nr - 1u;
    var pop = 0u;
    for (var m = 0u; m < tblMergeWords(); m++) {
      sMergePop[m] = pop;
      pop += countOneBits(staticBuf[info.mergeBase + m]);
    }
  }
  workgroupBarrier();

  // Interior vertices: rows 1..nl−1, columns 1..k_j (the last one is the row end E_j).
  for (var q = lid; q < info.interior; q += 64u) {
    let j = lastAtMost(false, 1u, nl - 1u, q);
    let col = q - sVertBase[j] + 1u;
    let u = select(sEnd[j], sBottom[col], col < sKept[j]);
    let v = sLeft[j];
    writeVertex(info.vertexBase + q, t, frameToCorners(f, ONE - u - v, u, v));
  }

  // Triangles: the clamped grid row strip by row strip, then the gap strip.
  for (var r = lid; r < info.triangles; r += 64u) {
    let out = info.triangleBase + r;
    if (r < info.gridTriangles) {
      let j = lastAtMost(true, 0u, nl - 1u, r);
      let local = r - sTriBase[j];
      let k0 = sKept[j];
      let k1 = sKept[j + 1u];
      let both = min(k0, k1);
      var i = local / 2u;
      var lower = (local & 1u) == 0u;
      if (local >= 2u * both) {
        i = both + (local - 2u * both);
        lower = k0 > k1;
      }
      if (lower) {
        writeTriangle(out, f, gridVertex(f, j, i), gridVertex(f, j, i + 1u), gridVertex(f, j + 1u, i + 1u));
      } else {
        writeTriangle(out, f, gridVertex(f, j, i), gridVertex(f, j + 1u, i + 1u), gridVertex(f, j + 1u, i));
      }
    } else {
      let g = r - info.gridTriangles; // merge step g (the last step, which closes at C, is never emitted)
      let a = innerStepsBefore(g);
      let b = g - a;
      if (mergeBit(g)) {
        writeTriangle(out, f, innerVertex(f, a), outerVertex(f, b), innerVertex(f, a + 1u));
      } else {
        writeTriangle(out, f, innerVertex(f, a), outerVertex(f, b), outerVertex(f, b + 1u));
      }
    }
  }
}
