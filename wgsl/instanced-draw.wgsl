// The instanced tessellator's vertex function, its render entry points and the headless compute
// pass that runs the same function (prepended: InstParams, wgsl/instanced-common.wgsl; appended:
// the surface module). What the headless pass writes is, vertex for vertex, what a draw shades.
//
//   work (u32, read-only here): the layout of wgsl/instanced-levels.wgsl (edge codes, lists)
//   bucket (uniform, one 256-byte slot per bucket, bound with a dynamic offset): INST_BUCKET in
//     src/gpu/instanced.ts: listBase (word offset of the bucket's list in work), level, domain,
//     baseVertex, firstIndex, vertexCount, triangleCount (of the level's pattern),
//     outVertexBase, outTriangleBase, instances (the headless pass only)
//   frame (uniform, render only): INST_FRAME: viewProj, lightViewProj, toLight, eye
//   headless outputs (storage, compute only): positions and normals (3 f32 per vertex), patch
//     (u32 per vertex), uv (2 f32 per vertex: the snapped pattern point / P), indices (3 u32 per
//     triangle). Each patch's pattern is written whole at outVertexBase + instance · vertexCount
//     and its triangles index it: vertices are shared within a patch, not across patch
//     boundaries (both sides of an edge write their own copy, which is what the crack check compares).

@group(0) @binding(3) var<storage, read> work: array<u32>;
@group(1) @binding(0) var<uniform> bucket: InstBucket;

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
// point (vertex_index includes the draw's baseVertex), snap, evaluate. Displacement would go
// here, after evalSurface (a vector displacement keeps the two sides of an edge equal, §6.6).
fn instancedVertex(instance: u32, vertexIndex: u32) -> InstancedVertex {
  let p = work[bucket.listBase + instance];
  let packed = staticBuf[params.offPatternIJ + vertexIndex];
  let P = bucket.level;
  let ij = snapVertex(p, P, packed & 0xffffu, packed >> 16u);
  let sp = patchSurface(p, P, ij.x, ij.y);
  return InstancedVertex(sp.pos, sp.normal, p, ij);
}

// ---- render --------------------------------------------------------------------------------

struct InstFrame { viewProj: mat4x4<f32>, lightViewProj: mat4x4<f32>, toLight: vec4<f32>, eye: vec4<f32> }
@group(2) @binding(0) var<uniform> frame: InstFrame;

struct VertexOut {
  @builtin(position) clip: vec4<f32>,
  @location(0) world: vec3<f32>,
  @location(1) normal: vec3<f32>,
}

@vertex
fn litVertex(@builtin(instance_index) instance: u32, @builtin(vertex_index) index: u32) -> VertexOut {
  let v = instancedVertex(instance, index);
  return VertexOut(frame.viewProj * vec4<f32>(v.pos, 1.0), v.pos, v.normal);
}

// Depth only, from the light: the shadow map pass re-evaluates the surface too (the point of
// comparing this tessellator with the compute one, which draws its stored mesh in every pass).
@vertex
fn shadowVertex(@builtin(instance_index) instance: u32, @builtin(vertex_index) index: u32) -> @builtin(position) vec4<f32> {
  return frame.lightViewProj * vec4<f32>(instancedVertex(instance, index).pos, 1.0);
}

@fragment
fn litFragment(in: VertexOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
  var n = normalize(in.normal);
  n = select(-n, n, front); // open surfaces: light the side that is seen
  let toEye = normalize(frame.eye.xyz - in.world);
  let h = normalize(frame.toLight.xyz + toEye);
  let albedo = select(vec3<f32>(0.28, 0.40, 0.56), vec3<f32>(0.70, 0.62, 0.52), front); // clay front, blue back
  let diffuse = max(dot(n, frame.toLight.xyz), 0.0);
  let c = albedo * (0.18 + 0.82 * diffuse) + vec3<f32>(0.12) * pow(max(dot(n, h), 0.0), 40.0);
  return vec4<f32>(c, 1.0);
}

// ---- headless ------------------------------------------------------------------------------

@group(2) @binding(1) var<storage, read_write> outPositions: array<f32>;
@group(2) @binding(2) var<storage, read_write> outNormals: array<f32>;
@group(2) @binding(3) var<storage, read_write> outPatch: array<u32>;
@group(2) @binding(4) var<storage, read_write> outUV: array<f32>;
@group(2) @binding(5) var<storage, read_write> outIndices: array<u32>;

// One thread per (instance, pattern vertex) and per (instance, pattern triangle) of one bucket.
@compute @workgroup_size(64)
fn headless(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let g = (wid.y * 65535u + wid.x) * 64u + lid;
  let nv = bucket.vertexCount;
  let nt = bucket.triangleCount;
  if (g < bucket.instances * nv) {
    let instance = g / nv;
    let k = g % nv;
    let v = instancedVertex(instance, bucket.baseVertex + k);
    let o = bucket.outVertexBase + g;
    for (var c = 0u; c < 3u; c++) {
      outPositions[3u * o + c] = v.pos[c];
      outNormals[3u * o + c] = v.normal[c];
    }
    outPatch[o] = v.patchId;
    outUV[2u * o] = f32(v.ij.x) / f32(bucket.level);
    outUV[2u * o + 1u] = f32(v.ij.y) / f32(bucket.level);
  }
  if (g < bucket.instances * nt) {
    let instance = g / nt;
    let t = g % nt;
    let base = bucket.outVertexBase + instance * nv;
    let o = bucket.outTriangleBase + g;
    for (var c = 0u; c < 3u; c++) {
      outIndices[3u * o + c] = base + staticBuf[params.offPatternIdx + bucket.firstIndex + 3u * t + c];
    }
  }
}
