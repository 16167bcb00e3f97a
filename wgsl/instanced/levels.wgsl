// Level selection and bucketing for the instanced tessellator (prepended: InstParams,
// wgsl/instanced/common.wgsl; appended: the surface module). No CPU readback: the last pass
// writes the indirect draw records that the render passes consume.
//
//   work (u32, atomics here), word offsets in InstParams:
//     wanted      1 per patch: the level asked for in per-patch mode (written by the CPU)
//     edgeCode    1 per edge: 7 − log2 L_e (0 = not yet set; cleared before each rebuild)
//     patchLevel  1 per patch: log2 of its pattern level P
//     counts      14: patches per bucket (bucket = domain · 7 + log2 P; cleared each rebuild)
//     lists       per bucket, its patch ids: bucket (domain, b) starts at
//                 domain 0: b · nQuads, domain 1: 7 · nQuads + b · nTris (a bucket can hold
//                 every patch of its domain, so no prefix sum is needed)
//   drawArgs (u32): 14 drawIndexedIndirect records of 5 words: indexCount, instanceCount,
//     firstIndex, baseVertex, firstInstance = 0 (a non-zero firstInstance needs the optional
//     'indirect-first-instance' feature; the bucket's list base reaches the vertex shader through
//     a uniform with a dynamic offset instead); then, from word 70, 14 drawIndirect
//     records of 4 words for the wireframe (wgsl/render/instanced.wgsl): vertexCount = 2 ×
//     indexCount (two line ends per triangle edge), instanceCount, 0, 0
//
// Modes (params.mode): 0 static (every patch wants params.staticLevel), 1 per patch (the wanted
// array), 2 dynamic (per edge, from the view: distance and curvature), 3 factor rule (per edge,
// the compute tessellator's adaptive rule). In modes 0 and 1 an edge's level is the minimum over
// its patches' levels and a patch keeps its own level; in modes 2 and 3 the edge's level is
// computed once per edge and the patch's level is the maximum over its edges.
// Either way both patches of an edge read the same stored value.

// Bindings (generated: src/gpu/instanced/buffer-layouts.ts INST_LEVELS_GROUP).


fn flatIndex(wid: vec3<u32>, lid: u32) -> u32 { return (wid.y * GRID_X + wid.x) * WORKGROUP_SIZE + lid; }

// A level as log2, rounded down to a power of two in [1, 64].
fn levelLog2(L: u32) -> u32 { return min(firstLeadingBit(max(L, 1u)), LEVELS - 1u); }

fn wantedLog2(p: u32) -> u32 {
  if (params.mode == 0u) { return levelLog2(params.staticLevel); }
  return levelLog2(atomicLoad(&work[params.offWanted + p]));
}

fn edgeLog2(e: u32) -> u32 { return LEVELS - atomicLoad(&work[params.offEdgeCode + e]); }

// Modes 0 and 1: every patch lowers its edges to its own level (max of 7 − log2 = min level).
@compute @workgroup_size(WORKGROUP_SIZE)
fn patchEdges(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let p = flatIndex(wid, lid);
  if (p >= params.nPatches) { return; }
  let code = LEVELS - wantedLog2(p);
  for (var k = 0u; k < patchEdgeCount(p); k++) {
    atomicMax(&work[params.offEdgeCode + patchEdge(p, k)], code);
  }
}

// Mode 2: the edge's level from the surface seen from the camera (this project's form; NVIDIA's
// 2009 sample blends the control polygon's screen length with an object-space term).
// Three points of the edge (its ends and middle, evaluated by the patch that owns it) are projected
// to pixels. Distance term: the chord's length over params.targetPixels. Curvature term: a curve
// whose middle departs d pixels from its chord is matched by N uniform segments within d / N²
// (exact for a quadratic), so N = sqrt(d / params.pixelError). L_e = the next power of two of
// lodScale · max of the two, in [1, 64]. An edge with a point behind the eye takes staticLevel.
@compute @workgroup_size(WORKGROUP_SIZE)
fn edgeView(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let e = flatIndex(wid, lid);
  if (e >= params.nEdges) { return; }
  let owner = staticBuf[params.offEdgeOwner + e];
  let p = instOwnerWord_patchId(owner);
  let k = instOwnerWord_side(owner);
  let isTri = patchIsTri(p);
  var s: array<vec2<f32>, 3>;
  var behind = false;
  for (var q = 0u; q < 3u; q++) {
    let ij = edgePoint(isTri, 2u, k, q);
    let clip = params.viewProj * vec4<f32>(patchSurface(p, 2u, ij.x, ij.y).pos, 1.0);
    behind = behind || clip.w <= 0.0;
    s[q] = clip.xy / max(clip.w, 1e-30) * 0.5 * params.viewport.xy;
  }
  var lg = levelLog2(params.staticLevel);
  if (!behind) {
    let chord = length(s[2] - s[0]);
    let dev = length(s[1] - 0.5 * (s[0] + s[2]));
    let n = params.lodScale * max(chord / params.targetPixels, sqrt(dev / params.pixelError));
    let m = u32(ceil(clamp(n, 1.0, f32(MAX_LEVEL))));
    lg = select(0u, firstLeadingBit(m - 1u) + 1u, m > 1u); // the next power of two ≥ m
  }
  atomicStore(&work[params.offEdgeCode + e], LEVELS - lg);
}

// Mode 3: the compute tessellator's adaptive factor rule (wgsl/tess/factors.wgsl adaptiveFactor,
// src/gpu/tess/factors.ts edgeFactor: the same screen-space measure, the same points), so that the two
// tessellators' triangle counts compare at one LOD scale. From the edge's two cage vertices'
// factorPoint (the surface's: the cage's positions and normals for Phong and ACC, the limit
// positions and normals at the cage vertices for Catmull-Clark, as the compute tessellator reads
// them): the Phong midpoint's offset e from the chord, k = sqrt(lodScale·|e| / (dist·pixelAngle)) with
// e's part across the line of sight counted twice on edges facing the eye (wgsl/tess/factor-rule.wgsl),
// 1 for an edge outside the frustum or facing away; then L_e = the next power of two ≥ ceil(k) in
// [1, 64] (rounded up: at least the compute tessellator's segments, so its pixel error bound holds).
fn edgeEnd(p: u32, isTri: bool, k: u32, t: u32) -> u32 {
  let ij = edgePoint(isTri, 1u, k, t);
  let pt = patchTriangle(p, 1u, ij.x, ij.y);
  return triVert(pt.t, select(select(2u, 1u, pt.w.y == ONE), 0u, pt.w.x == ONE));
}

fn factorSphereOutside(c: vec3<f32>, r: f32) -> bool {
  let m = transpose(params.viewProj); // rows of viewProj
  let planes = array<vec4<f32>, 6>(m[3] + m[0], m[3] - m[0], m[3] + m[1], m[3] - m[1], m[2], m[3] - m[2]);
  for (var i = 0u; i < 6u; i++) {
    let q = planes[i];
    if (dot(q.xyz, c) + q.w < -r * length(q.xyz)) { return true; }
  }
  return false;
}

@compute @workgroup_size(WORKGROUP_SIZE)
fn edgeFactorRule(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let e = flatIndex(wid, lid);
  if (e >= params.nEdges) { return; }
  let owner = staticBuf[params.offEdgeOwner + e];
  let p = instOwnerWord_patchId(owner);
  let k = instOwnerWord_side(owner);
  let isTri = patchIsTri(p);
  let a = factorPoint(edgeEnd(p, isTri, k, 0u));
  let b = factorPoint(edgeEnd(p, isTri, k, 1u));
  let bend = edgeBend(a.pos, a.normal, b.pos, b.normal, params.eye.xyz);
  var f = 1.0;
  if (!(bend.away || factorSphereOutside(bend.mid, 0.5 * length(b.pos - a.pos) + length(bend.off)))) {
    f = bendFactor(bend, params.eye.xyz, params.lodScale, params.pixelAngle);
  }
  f = select(1.0, min(f, f32(MAX_LEVEL)), f >= 1.0); // NaN and ≤ 1: 1
  let m = u32(ceil(f));
  let lg = select(0u, firstLeadingBit(m - 1u) + 1u, m > 1u); // the next power of two ≥ m
  atomicStore(&work[params.offEdgeCode + e], LEVELS - lg);
}

// Every patch: its pattern level, then a slot in its bucket's list.
@compute @workgroup_size(WORKGROUP_SIZE)
fn bucketPatches(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let p = flatIndex(wid, lid);
  if (p >= params.nPatches) { return; }
  var lg = 0u;
  if (params.mode >= 2u) {
    for (var k = 0u; k < patchEdgeCount(p); k++) { lg = max(lg, edgeLog2(patchEdge(p, k))); }
  } else {
    lg = wantedLog2(p);
  }
  atomicStore(&work[params.offPatchLevel + p], lg);
  let domain = select(0u, 1u, patchIsTri(p));
  let slot = atomicAdd(&work[params.offCounts + domain * LEVELS + lg], 1u);
  let base = select(lg * params.nQuads, LEVELS * params.nQuads + lg * params.nTris, domain == 1u);
  atomicStore(&work[params.offLists + base + slot], p);
}

// One thread per bucket: its drawIndexedIndirect record.
@compute @workgroup_size(RECORD_THREADS)
fn records(@builtin(local_invocation_index) b: u32) {
  if (b >= 2u * LEVELS) { return; }
  let domain = b / LEVELS;
  let lg = b % LEVELS;
  drawArgs[5u * b + 0u] = entryWord(domain, lg, 2u);
  drawArgs[5u * b + 1u] = atomicLoad(&work[params.offCounts + b]);
  drawArgs[5u * b + 2u] = entryWord(domain, lg, 1u);
  drawArgs[5u * b + 3u] = entryWord(domain, lg, 0u);
  drawArgs[5u * b + 4u] = 0u;
  let w = 5u * 2u * LEVELS + 4u * b;
  drawArgs[w] = 2u * entryWord(domain, lg, 2u);
  drawArgs[w + 1u] = drawArgs[5u * b + 1u];
  drawArgs[w + 2u] = 0u;
  drawArgs[w + 3u] = 0u;
}
