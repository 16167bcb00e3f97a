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
// Both are threads of the one output dispatch (wgsl/tess/emit.wgsl `vertices`), which asks here
// where its vertex lies (a VertexPlace) and evaluates every kind of vertex at one call site.
//
// Where normals split, a point's copies share one position: the copy on the owner's side
// evaluates it and writes it, into its twin's slot too where it knows it (an edge's second copy
// lies interior − 1 slots on), and each other copy evaluates only its own side for its normal. An
// extra sector's position (several sectors of a vertex, found from the sector alone) gets a
// thread of its own after all the vertices (extraSlotPosition). So each thread evaluates the
// surface once, with no loop round the evaluator (a loop of one or two evaluations per thread
// cost the exact surface's emit about an eighth of its time on SwiftShader).

// What an output vertex's thread evaluates and writes: the surface at (t, w), into output vertex
// `index`: its position (VERTEX_POSITION, and at `posAlso` unless NO_OWNER), its normal,
// barycentrics and source triangle (VERTEX_SHADING); `unused` marks a cage vertex that no face
// with a surface uses (cage: outputs.wgsl writeUnusedVertex).
const VERTEX_POSITION: u32 = 1u;
const VERTEX_SHADING: u32 = 2u;
struct VertexPlace { index: u32, t: u32, w: vec3<u32>, writes: u32, posAlso: u32, unused: bool }

fn cornerWeights(corner: u32) -> vec3<u32> {
  var w = vec3<u32>(0u);
  w[corner] = ONE;
  return w;
}

// Output vertex v < nSlots: a cage vertex (through its owner), or an extra sector of one (its
// normal through its own triangle; its position is extraSlotPosition's).
fn cornerPlace(v: u32) -> VertexPlace {
  if (v >= params.nVerts) {
    let sector = staticBuf[params.offSlotOwner + v - params.nVerts];
    return VertexPlace(v, ownerWord_tri(sector), cornerWeights(ownerWord_corner(sector)), VERTEX_SHADING, NO_OWNER, false);
  }
  let owner = staticBuf[params.offVertexOwner + v];
  return VertexPlace(v, ownerWord_tri(owner), cornerWeights(ownerWord_corner(owner)), VERTEX_POSITION | VERTEX_SHADING, NO_OWNER, owner == NO_OWNER);
}

// The position of extra sector slot nVerts + j: its vertex's, through the vertex's owner (the
// same evaluation as the vertex's own slot, so bit-identical).
fn extraSlotPosition(j: u32) -> VertexPlace {
  let sector = staticBuf[params.offSlotOwner + j];
  let owner = staticBuf[params.offVertexOwner + triVert(ownerWord_tri(sector), ownerWord_corner(sector))];
  return VertexPlace(params.nVerts + j, ownerWord_tri(owner), cornerWeights(ownerWord_corner(owner)), VERTEX_POSITION, NO_OWNER, false);
}

// The q-th interior edge point of the whole mesh (output vertex nSlots + q).
fn edgePlace(q: u32) -> VertexPlace {
  let e = lastAtMost(params.offEdgeBase, params.nEdges, q);
  let j = q - work[params.offEdgeBase + e];
  let interior = edgeSegments(e) - 1u;
  let twinSide = j >= interior; // only where the edge splits: its second copy
  let k = select(j, j - interior, twinSide) + 1u; // point k of the edge's line, 1..n−1
  let x = linePoint(edgeState(e), edgeF(e), k);
  let index = params.nSlots + q;
  if (twinSide) {
    // The second copy: its normal through the twin; its position is the first copy's.
    let twin = staticBuf[params.offEdgeTwin + e];
    return VertexPlace(index, ownerWord_tri(twin), edgeWeights(e, twin, x), VERTEX_SHADING, NO_OWNER, false);
  }
  let owner = staticBuf[params.offEdgeOwner + e];
  let also = select(NO_OWNER, index + interior, edgeSplit(e));
  return VertexPlace(index, ownerWord_tri(owner), edgeWeights(e, owner, x), VERTEX_POSITION | VERTEX_SHADING, also, false);
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
