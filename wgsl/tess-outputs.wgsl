// The output mesh (src/gpu/types.ts), for the emit passes.
@group(0) @binding(4) var<storage, read_write> outPositions: array<f32>;
@group(0) @binding(5) var<storage, read_write> outNormals: array<f32>;
@group(0) @binding(6) var<storage, read_write> outBary: array<u32>;
@group(0) @binding(7) var<storage, read_write> outSrcTri: array<u32>;

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
