// After the bulge, one thread per triangle, at every budget candidate: its edges' factors, and how many interior vertices and how
// many triangles its clamped-parallelogram pattern has (edge and corner vertices belong to
// the edges and corners, and are counted there). Same construction as src/pattern/clamped.ts:
//   rows j = 0..nl, row 0 keeps k_0 columns (wgsl/tess/pattern.wgsl rowZeroKept), row j ≥ 1 keeps
//   k_j = #{u_i < c − v_j}, row nl is the corner C; interior vertices = Σ_{0<j<nl} k_j;
//   triangles = Σ_{j<nl} (k_j + k_{j+1}) (the grid) + (nb − 1 − k_0) + nl + nr − 1 (the gap
//   strip: its inner chain has the nb − 1 − k_0 bottom points past u_{k_0} too), in which k_0
//   cancels, so it is not needed here.

@compute @workgroup_size(WORKGROUP_SIZE)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let t = flatIndex(wid, lid);
  if (t >= params.nTris) { return; }
  // The triangle's three edges' factors, computed here rather than in a pass of their own (one
  // dispatch fewer): the edge's other triangle computes the same bits by the same code (one call
  // site, in this loop), and the edge's owner stores the factor for the scan's last pass, which
  // stores the edge's line at the chosen candidate for the passes after the budget.
  var edges: vec3<u32>;
  var f0: vec3<f32>;
  var owns: vec3<bool>;
  for (var i = 0u; i < 3u; i++) {
    let e = triEdge(t, i);
    edges[i] = e;
    f0[i] = edgeFactor(e);
    owns[i] = ownerWord_tri(staticBuf[params.offEdgeOwner + e]) == t;
  }
  for (var i = 0u; i < 3u; i++) {
    if (owns[i]) { work[params.offEdgeFactor + edges[i]] = bitcast<u32>(f0[i]); }
  }
  useLocalEdges = true;
  // At every budget candidate, so that the budget can choose after one scan (contract/tess.ts
  // BUDGET_SCALES): lane c of each array holds candidate c.
  for (var c = 0u; c < BUDGET_CANDIDATES; c++) {
    for (var i = 0u; i < 3u; i++) {
      let l = edgeAtCandidate(f0[i], c);
      localEdgeLines[i] = l;
      if (owns[i]) {
        // Its interior points, twice on an edge whose normals split (once per side).
        work[params.offEdgeInterior + c * params.nEdges + edges[i]] = (l.z - 1u) * select(1u, 2u, edgeSplit(edges[i]));
      }
    }
    let L = triLines(t);
    var interior = 0u;
    var triangles = L.bottom.n - 1u; // k_0 + (nb − 1 − k_0)
    for (var j = 1u; j < L.left.n; j++) {
      let k = keptColumns(L.bottom, rowEnd(L, j));
      interior += k;
      triangles += 2u * k;
    }
    // Σ_{j<nl}(k_j + k_{j+1}) = k_0 + 2·Σ_{0<j<nl} k_j + k_nl, with k_nl = 0.
    triangles += L.left.n + L.right.n - 1u;
    let at = c * params.nTris + t;
    work[params.offTriVertCount + at] = interior;
    work[params.offTriTriCount + at] = triangles;
    work[params.offTriRowCount + at] = L.left.n + 1u; // rows 0..nl, for the plan
  }
}
