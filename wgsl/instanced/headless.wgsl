// The instanced tessellator's vertex function run in compute over every instance of one bucket
// (prepended: the vertex function, wgsl/instanced/draw.wgsl): checks and the CLI read exactly
// what a draw shades.
//
//   headless output (storage, group 2; ONE buffer, so that an ACC surface's two and a displacement
//   lender's two fit the per-stage limit of 8 storage buffers): outWords, u32 words: 8 per vertex
//   (position, normal, uv: the snapped pattern point / P; f32 bits), then the patch of each vertex
//   (bucket.outVertexTotal of them), then 3 indices per triangle. Each patch's pattern is written whole at outVertexBase + instance · vertexCount
//     and its triangles index it: vertices are shared within a patch, not across patch
//     boundaries (both sides of an edge write their own copy, which is what the crack check compares).

// Its binding is generated (src/gpu/instanced/buffer-layouts.ts INST_HEADLESS_GROUP).

// One thread per (instance, pattern vertex) and per (instance, pattern triangle) of one bucket.
@compute @workgroup_size(WORKGROUP_SIZE)
fn headless(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let g = (wid.y * GRID_X + wid.x) * WORKGROUP_SIZE + lid;
  let nv = bucket.vertexCount;
  let nt = bucket.triangleCount;
  if (g < bucket.instances * nv) {
    let instance = g / nv;
    let k = g % nv;
    let v = instancedVertex(instance, bucket.baseVertex + k);
    let o = bucket.outVertexBase + g;
    for (var c = 0u; c < 3u; c++) {
      outWords[8u * o + c] = bitcast<u32>(v.pos[c]);
      outWords[8u * o + 3u + c] = bitcast<u32>(v.normal[c]);
    }
    outWords[8u * o + 6u] = bitcast<u32>(f32(v.ij.x) / f32(bucket.level));
    outWords[8u * o + 7u] = bitcast<u32>(f32(v.ij.y) / f32(bucket.level));
    outWords[8u * bucket.outVertexTotal + o] = v.patchId;
  }
  if (g < bucket.instances * nt) {
    let instance = g / nt;
    let t = g % nt;
    let base = bucket.outVertexBase + instance * nv;
    let o = bucket.outTriangleBase + g;
    for (var c = 0u; c < 3u; c++) {
      outWords[9u * bucket.outVertexTotal + 3u * o + c] = base + staticBuf[params.offPatternIdx + bucket.firstIndex + 3u * t + c];
    }
  }
}
