// Writing one vertex of the output mesh (src/gpu/contract/tessellated-mesh.ts), for the emit pass.

// The emit's vertices are compiled per mesh (src/gpu/tess/tessellator.ts pipelineOf): with
// DISPLACED false, none of the displacement's code, until a mesh is displaced. A path a shader
// never runs is not free: on a GPU it takes registers from every thread; on SwiftShader (CI,
// headless runs) the displacement compiled in but switched off made the vertices' emit of bigguy
// at fixed 16 about 40 % slower on either surface. The surface's own cases are compiled out the
// same way (wgsl/cc/surface.wgsl).
override DISPLACED: bool = true;

// The surface point of triangle t at weights w, displaced when params.dispOn (wgsl/tess/displace.wgsl).
fn surfaceAt(t: u32, w: vec3<u32>) -> SurfacePoint {
  let s = evalSurface(t, w);
  if (!DISPLACED || params.dispOn == 0u) { return s; }
  return displacePoint(t, w, s);
}

// One output vertex (wgsl/tess/weld.wgsl VertexPlace): the surface at (P.t, P.w), evaluated
// once, and what of it this thread writes. The surface is called from ONE place: a shader
// compiler that inlines every call (SwiftShader's, which CI and headless runs use) builds the
// exact surface's evaluator once per call site, and three sites per weld entry point made the
// weld most of a page's pipeline build (4.2 + 4.5 s of 16 s on 2 CPU cores). Every kind of
// vertex comes through here for the same reason (wgsl/tess/emit.wgsl `vertices`).
fn writeVertex(P: VertexPlace) {
  let s = surfaceAt(P.t, P.w); // displaced when on (wgsl/tess/displace.wgsl)
  if ((P.writes & VERTEX_POSITION) != 0u) {
    writePosition(P.index, s.pos);
    writePosition(P.posAlso, s.pos);
  }
  if ((P.writes & VERTEX_SHADING) == 0u || P.index >= params.vertexCapacity) { return; }
  let index = P.index;
  outNormals[3u * index] = s.normal.x;
  outNormals[3u * index + 1u] = s.normal.y;
  outNormals[3u * index + 2u] = s.normal.z;
  outBary[index] = packBary(P.w);
  outSrcTri[index] = P.t;
}

// Output vertex `index`'s position (none for NO_OWNER, or past the output buffers).
fn writePosition(index: u32, p: vec3<f32>) {
  if (index >= params.vertexCapacity) { return; }
  outPositions[3u * index] = p.x;
  outPositions[3u * index + 1u] = p.y;
  outPositions[3u * index + 2u] = p.z;
}

// A cage vertex no face with a surface uses (a bare vertex, or one of holes only) still has its
// output slot: it gets the cage position, no normal and no source triangle (NO_OWNER), so the
// output buffers never hold what a previous mesh left there. No triangle refers to it.
fn writeUnusedVertex(index: u32, v: u32) {
  if (index >= params.vertexCapacity) { return; }
  writePosition(index, cagePos(v));
  outNormals[3u * index] = 0.0;
  outNormals[3u * index + 1u] = 0.0;
  outNormals[3u * index + 2u] = 0.0;
  outBary[index] = 0u;
  outSrcTri[index] = NO_OWNER;
}
