// Writing one vertex of the output mesh (src/gpu/contract/tessellated-mesh.ts), for the emit pass.

// The emit's vertices are built twice from this code (src/gpu/tess/passes.ts): emitVertices with
// DISPLACED false, which has none of the displacement's code, and emitVerticesDisplaced, made when
// a mesh is first displaced. A path a shader never runs is not free: on a GPU it takes registers
// from every thread; on SwiftShader (CI, headless runs) the displacement compiled in but switched
// off made the vertices' emit of bigguy at fixed 16 about 40 % slower on either surface.
override DISPLACED: bool = true;

// The surface point of triangle t at weights w, displaced when params.dispOn (wgsl/tess/displace.wgsl).
fn surfaceAt(t: u32, w: vec3<u32>) -> SurfacePoint {
  let s = evalSurface(t, w);
  if (!DISPLACED || params.dispOn == 0u) { return s; }
  return displacePoint(t, w, s);
}

// A point where the surface's normal splits (an infinitely sharp crease): the position of the
// point as (tPos, wPos) gives it, the owner side's, so that both sides' output vertices lie at
// bit-identical places (one evaluation, repeated exactly), and the normal as triangle tN sees it.
// Where (tN, wN) is (tPos, wPos) (every vertex but a split one) the point is evaluated once.
//
// The surface is called from ONE place, in a loop of one or two turns, not once per side: a
// shader compiler that inlines every call (SwiftShader's, which CI and headless runs use) builds
// the exact surface's evaluator once per call site, and three sites per weld entry point made the
// weld most of a page's pipeline build (4.2 + 4.5 s of 16 s on 2 CPU cores). Every kind of
// vertex comes through writeSplitVertex for the same reason (wgsl/tess/emit.wgsl `output`).
fn writeSplitVertex(index: u32, tPos: u32, wPos: vec3<u32>, tN: u32, wN: vec3<u32>) {
  if (index >= params.vertexCapacity) { return; }
  let turns = select(1u, 2u, tN != tPos || any(wN != wPos));
  var p = vec3<f32>(0.0);
  var n = vec3<f32>(0.0);
  for (var k = 0u; k < turns; k++) {
    let s = surfaceAt(select(tPos, tN, k == 1u), select(wPos, wN, k == 1u)); // displaced when on (wgsl/tess/displace.wgsl)
    if (k == 0u) { p = s.pos; }
    n = s.normal;
  }
  outPositions[3u * index] = p.x;
  outPositions[3u * index + 1u] = p.y;
  outPositions[3u * index + 2u] = p.z;
  outNormals[3u * index] = n.x;
  outNormals[3u * index + 1u] = n.y;
  outNormals[3u * index + 2u] = n.z;
  outBary[index] = packBary(wN);
  outSrcTri[index] = tN;
}

// A cage vertex no face with a surface uses (a bare vertex, or one of holes only) still has its
// output slot: it gets the cage position, no normal and no source triangle (NO_OWNER), so the
// output buffers never hold what a previous mesh left there. No triangle refers to it.
fn writeUnusedVertex(index: u32, v: u32) {
  if (index >= params.vertexCapacity) { return; }
  let p = cagePos(v);
  outPositions[3u * index] = p.x;
  outPositions[3u * index + 1u] = p.y;
  outPositions[3u * index + 2u] = p.z;
  outNormals[3u * index] = 0.0;
  outNormals[3u * index + 1u] = 0.0;
  outNormals[3u * index + 2u] = 0.0;
  outBary[index] = 0u;
  outSrcTri[index] = NO_OWNER;
}
