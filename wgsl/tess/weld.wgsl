// The weld. Every vertex that two or more triangles share is evaluated exactly once, here, and
// every triangle refers to it by index, so the output is watertight by construction: the
// vertices on shared corners and shared edges are not just bit-identical, they are one. (Where
// normals split at a crease, a point has one vertex per side: those are bit-identical, both
// positions being the same evaluation, as the instanced tessellator's owner rule is.)
//   corners: vertex v of the output is cage vertex v (Phong tessellation interpolates its
//            corners), one thread per cage vertex, then one per extra sector of a vertex where
//            the normals split (prepare.ts splitCreases: its position is the vertex's, its normal
//            the sector's);
//   edges:   the interior points of each mesh edge's line, in the edge's canonical direction
//            (lower to higher vertex), one thread per point (a thread per edge looping over its
//            points made the pass as slow as its most finely cut edge, 1.4-3 ms on an H200 at
//            factor 16); each is evaluated through one triangle of the edge, whose barycentrics
//            are stored. An edge whose normals split has its points twice: the owner's, then
//            the twin's (same positions).
// Both are threads of the one output dispatch (wgsl/tess/emit.wgsl `output`), which asks here
// where its vertex lies (a VertexPlace) and evaluates every kind of vertex at one call site.

// Where an output vertex lies: its position through (tPos, wPos), its normal through (tN, wN)
// (the same but where normals split: outputs.wgsl writeSplitVertex); `unused` marks a cage
// vertex that no face with a surface uses (cage: outputs.wgsl writeUnusedVertex).
struct VertexPlace { tPos: u32, wPos: vec3<u32>, tN: u32, wN: vec3<u32>, unused: bool }

// Output vertex v < nSlots: a cage vertex, or an extra sector of one.
fn cornerPlace(v: u32) -> VertexPlace {
  var P = VertexPlace(0u, vec3<u32>(0u), 0u, vec3<u32>(0u), false);
  if (v >= params.nVerts) {
    // An extra sector: the normal through its own triangle, the position through the vertex's owner.
    let sector = staticBuf[params.offSlotOwner + v - params.nVerts];
    let ts = ownerWord_tri(sector);
    let cv = triVert(ts, ownerWord_corner(sector));
    let owner = staticBuf[params.offVertexOwner + cv];
    P.tPos = ownerWord_tri(owner);
    P.wPos[ownerWord_corner(owner)] = ONE;
    P.tN = ts;
    P.wN[ownerWord_corner(sector)] = ONE;
    return P;
  }
  let owner = staticBuf[params.offVertexOwner + v];
  P.unused = owner == NO_OWNER;
  if (P.unused) { return P; }
  P.tPos = ownerWord_tri(owner);
  P.wPos[ownerWord_corner(owner)] = ONE;
  P.tN = P.tPos;
  P.wN = P.wPos;
  return P;
}

// The q-th interior edge point of the whole mesh (output vertex nSlots + q).
fn edgePlace(q: u32) -> VertexPlace {
  let e = lastAtMost(params.offEdgeBase, params.nEdges, q);
  let j = q - work[params.offEdgeBase + e];
  let interior = edgeSegments(e) - 1u;
  let twinSide = j >= interior; // only where the edge splits: its second copy
  let k = select(j, j - interior, twinSide) + 1u; // point k of the edge's line, 1..n−1
  let x = linePoint(edgeState(e), edgeF(e), k);
  let owner = staticBuf[params.offEdgeOwner + e];
  let t = ownerWord_tri(owner);
  let w = edgeWeights(e, owner, x);
  // The normal's side: the owner's, or on an edge's second copy its twin's.
  var P = VertexPlace(t, w, t, w, false);
  if (twinSide) {
    let twin = staticBuf[params.offEdgeTwin + e];
    P.tN = ownerWord_tri(twin);
    P.wN = edgeWeights(e, twin, x);
  }
  return P;
}

// The weights of edge e's point x (a line coordinate along the edge's canonical direction) in
// one of its triangles, given as an OwnerWord (the triangle and the corner its edge starts at).
fn edgeWeights(e: u32, side: u32, x: u32) -> vec3<u32> {
  let t = ownerWord_tri(side);
  let i = ownerWord_corner(side); // the triangle's edge i runs from its corner i to corner i+1
  let forward = triVert(t, i) == edgeVert(e, 0u);
  let tw = select(ONE - x, x, forward); // weight of corner i+1
  var w = vec3<u32>(0u);
  w[(i + 1u) % 3u] = tw;
  w[i] = ONE - tw;
  return w;
}
