// Writing one vertex of the output mesh (src/gpu/types.ts), for the weld and emit passes.

fn writeVertex(index: u32, t: u32, w: vec3<u32>) {
  if (index >= params.vertexCapacity) { return; }
  let s = evalSurface(t, w);
  outPositions[3u * index] = s.pos.x;
  outPositions[3u * index + 1u] = s.pos.y;
  outPositions[3u * index + 2u] = s.pos.z;
  outNormals[3u * index] = s.normal.x;
  outNormals[3u * index + 1u] = s.normal.y;
  outNormals[3u * index + 2u] = s.normal.z;
  outBary[index] = packBary(w);
  outSrcTri[index] = t;
}
