// Catmull-Clark patch build ("subdivision"), run whenever the cage moves. `struct Params` is
// generated from src/gpu/tessellator.ts and prepended. The control points of every patch, of
// every blended leaf's limit point and of every cage vertex's limit are weighted sums of the
// cage positions (stencils, src/gpu/cc/build.ts); they are written after the cage positions
// and normals in cageBuf, where the emit passes (wgsl/surface-cc.wgsl) read them.

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> staticBuf: array<u32>;
@group(0) @binding(2) var<storage, read_write> cageBuf: array<f32>;

const GRID_X: u32 = 65535u;

fn cagePosRW(v: u32) -> vec3<f32> { return vec3<f32>(cageBuf[3u * v], cageBuf[3u * v + 1u], cageBuf[3u * v + 2u]); }
fn ctrlRW(i: u32) -> vec3<f32> {
  let o = params.offCtrl + 3u * i;
  return vec3<f32>(cageBuf[o], cageBuf[o + 1u], cageBuf[o + 2u]);
}

// One thread per control point: its stencil applied to the current cage positions.
@compute @workgroup_size(64)
fn points(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let i = (wid.y * GRID_X + wid.x) * 64u + lid;
  if (i >= params.nCtrl) { return; }
  let e0 = staticBuf[params.ccRows + i];
  let e1 = staticBuf[params.ccRows + i + 1u];
  var p = vec3<f32>(0.0);
  for (var e = e0; e < e1; e++) {
    let v = staticBuf[params.ccEntries + 2u * e];
    let w = bitcast<f32>(staticBuf[params.ccEntries + 2u * e + 1u]);
    p += w * cagePosRW(v);
  }
  let o = params.offCtrl + 3u * i;
  cageBuf[o] = p.x;
  cageBuf[o + 1u] = p.y;
  cageBuf[o + 2u] = p.z;
}

// One thread per cage vertex: its limit position and normal, where the factor rule and the
// flat baseline read them.
@compute @workgroup_size(64)
fn limits(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let v = (wid.y * GRID_X + wid.x) * 64u + lid;
  if (v >= params.nVerts) { return; }
  let b = params.ccVertexLimits + 3u * v;
  let p = ctrlRW(b);
  let n = cross(ctrlRW(b + 1u), ctrlRW(b + 2u));
  let l = length(n);
  var nn = vec3<f32>(cageBuf[params.offNormals + 3u * v], cageBuf[params.offNormals + 3u * v + 1u], cageBuf[params.offNormals + 3u * v + 2u]);
  if (l > 0.0) { nn = n / l; }
  let op = params.offFactorPos + 3u * v;
  let on = params.offFactorNormal + 3u * v;
  cageBuf[op] = p.x;
  cageBuf[op + 1u] = p.y;
  cageBuf[op + 2u] = p.z;
  cageBuf[on] = nn.x;
  cageBuf[on + 1u] = nn.y;
  cageBuf[on + 2u] = nn.z;
}
