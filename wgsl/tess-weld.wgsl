// The weld. Every vertex that two or more triangles share is evaluated exactly once, here, and
// every triangle refers to it by index, so the output is watertight by construction: the
// vertices on shared corners and shared edges are not just bit-identical, they are one.
//   corners: vertex v of the output is cage vertex v (Phong tessellation interpolates its
//            corners), one thread per cage vertex;
//   edges:   the interior points of each mesh edge's line, in the edge's canonical direction
//            (lower to higher vertex), one thread per point (an indirect dispatch sized by the
//            budget pass: a thread per edge looping over its points made the pass as slow as
//            its most finely cut edge, 1.4-3 ms on an H200 at factor 16); each is evaluated
//            through one triangle of the edge, whose barycentrics are stored.

@compute @workgroup_size(WORKGROUP_SIZE)
fn corners(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let v = flatIndex(wid, lid);
  if (v >= params.nVerts || !emitEnabled()) { return; }
  let owner = staticBuf[params.offVertexOwner + v];
  if (owner == NO_OWNER) {
    writeUnusedVertex(v, v); // not used by any face with a surface
    return;
  }
  let t = ownerWord_tri(owner);
  var w = vec3<u32>(0u);
  w[ownerWord_corner(owner)] = ONE;
  writeVertex(v, t, w);
}

@compute @workgroup_size(WORKGROUP_SIZE)
fn edges(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let q = flatIndex(wid, lid); // the q-th interior edge point of the whole mesh
  if (q >= work[params.offEdgeBase + params.nEdges] || !emitEnabled()) { return; }
  let e = lastAtMost(params.offEdgeBase, params.nEdges, q);
  let k = q - work[params.offEdgeBase + e] + 1u; // point k of the edge's line, 1..n−1
  let owner = staticBuf[params.offEdgeOwner + e];
  let t = ownerWord_tri(owner);
  let i = ownerWord_corner(owner); // the owner's edge i runs from its corner i to corner i+1
  let forward = triVert(t, i) == edgeVert(e, 0u);
  let x = linePoint(edgeState(e), edgeF(e), k);
  let tw = select(ONE - x, x, forward); // weight of corner i+1
  var w = vec3<u32>(0u);
  w[(i + 1u) % 3u] = tw;
  w[i] = ONE - tw;
  writeVertex(params.nVerts + q, t, w);
}
