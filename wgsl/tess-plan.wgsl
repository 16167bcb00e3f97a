// Plan, once the budget has accepted the counts: one thread per cage triangle writes its
// pattern's rows (rows 0..nl at the triangle's row offset from the prefix sums), two words each:
//   k_j  the columns the row keeps (row 0: nb − 1; row nl, the corner C: 0)
//   S_j  Σ_{j'<j} k_j', from which the emit passes find a row by binary search:
//        interior vertices before row j (j ≥ 1) = S_j − k_0,
//        grid triangles before row strip j     = 2·S_j + k_j − k_0.
// With the rows planned, every output vertex and triangle is written by its own thread (emit):
// no workgroup memory and no barriers, so the work is spread evenly whatever the factors.

@compute @workgroup_size(WORKGROUP_SIZE)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let t = flatIndex(wid, lid);
  if (t >= params.nTris || !emitEnabled()) { return; }
  let L = triLines(t);
  let first = work[params.offTriRowBase + t];
  var cum = 0u;
  for (var j = 0u; j <= L.left.n; j++) {
    var k = 0u;
    if (j == 0u) { k = L.bottom.n - 1u; } else if (j < L.left.n) { k = keptColumns(L.bottom, rowEnd(L, j)); }
    let o = params.offRows + 2u * (first + j);
    work[o] = k;
    work[o + 1u] = cum;
    cum += k;
  }
}
