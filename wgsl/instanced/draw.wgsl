// The instanced tessellator's vertex function (prepended: InstParams, InstBucket,
// wgsl/instanced/common.wgsl; appended: the surface module). Its callers, each in a module of its
// own: wgsl/instanced/frame.wgsl (a draw with its own frame uniform and shading),
// wgsl/render/instanced.wgsl (the demo renderer's lit, shadow and wireframe passes) and
// wgsl/instanced/headless.wgsl (the same function in compute, for checks and the CLI). What the
// headless pass writes is, vertex for vertex, what a draw shades.
//
//   work (u32, read-only here): the layout of wgsl/instanced/levels.wgsl (edge codes, lists)
//   bucket (uniform, one 256-byte slot per bucket, bound with a dynamic offset): INST_BUCKET in
//     src/gpu/instanced/buffer-layouts.ts: listBase (word offset of the bucket's list in work), level, domain,
//     baseVertex, firstIndex, vertexCount, triangleCount (of the level's pattern),
//     outVertexBase, outTriangleBase, instances (the headless pass only)

// Bindings (generated: src/gpu/instanced/buffer-layouts.ts INST_DRAW_MESH_GROUP, INST_BUCKET_GROUP).

// Snapped pattern coordinates of vertex (i, j) of patch p at level P (src/pattern/pow2.ts
// snapVertex): only a vertex on exactly one edge moves, along that edge, to the edge's level,
// rounding down in the canonical direction so both patches of the edge land on the same points.
fn snapVertex(p: u32, P: u32, i: u32, j: u32) -> vec2<u32> {
  let isTri = patchIsTri(p);
  var k = 4u;
  var t = 0u;
  var on = 0u;
  if (j == 0u) { k = 0u; t = i; on++; }
  if (isTri) {
    if (i + j == P) { k = 1u; t = j; on++; }
    if (i == 0u) { k = 2u; t = P - j; on++; }
  } else {
    if (i == P) { k = 1u; t = j; on++; }
    if (j == P) { k = 2u; t = P - i; on++; }
    if (i == 0u) { k = 3u; t = P - j; on++; }
  }
  if (on != 1u) { return vec2<u32>(i, j); }
  let Le = 1u << (LEVELS - work[params.offEdgeCode + patchEdge(p, k)]);
  let R = P / min(Le, P);
  var ts = (t / R) * R;
  if (!patchCanonical(p, k)) { ts = P - ((P - t) / R) * R; }
  return edgePoint(isTri, P, k, ts);
}

struct InstancedVertex { pos: vec3<f32>, normal: vec3<f32>, patchId: u32, ij: vec2<u32> }

// The vertex function: instance → patch (through the bucket's list), vertex_index → pattern
// point (vertex_index includes the draw's baseVertex), snap, evaluate (vertexSurface:
// wgsl/instanced/vertex-plain.wgsl, or with displacement wgsl/instanced/displace.wgsl, which
// evaluates boundary points through their owner triangle and displaces after the surface).
fn instancedVertex(instance: u32, vertexIndex: u32) -> InstancedVertex {
  let p = work[bucket.listBase + instance];
  let packed = staticBuf[params.offPatternIJ + vertexIndex];
  let P = bucket.level;
  let ij = snapVertex(p, P, packed & 0xffffu, packed >> 16u);
  let sp = vertexSurface(p, P, ij.x, ij.y);
  return InstancedVertex(sp.pos, sp.normal, p, ij);
}
