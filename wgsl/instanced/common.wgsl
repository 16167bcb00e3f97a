// Shared by the instanced tessellator's passes (src/gpu/instanced/instanced.ts). `struct InstParams` is
// generated from src/gpu/instanced/buffer-layouts.ts INST_PARAMS and prepended; the surface module (a file that
// defines `fn evalSurface(t: u32, wFixed: vec3<u32>) -> SurfacePoint`, e.g.
// wgsl/surface/phong.wgsl, unchanged) is appended.
//
// Buffers:
//   staticBuf  u32 words, written once per cage (src/gpu/instanced/levels.ts setMesh):
//                triVerts   3 per cage triangle (src/gpu/tess/prepare.ts: quads split along 0–2,
//                           n-gons fanned round a centre vertex)
//                patches    PATCH_WORDS per patch: firstTri, flags, e0, e1, e2, e3, face, 0
//                           flags bit 0: triangle domain; bit 1 + k: edge k walked canonically
//                           (its corner k has the lower cage vertex id); patches are the quads
//                           (ids 0 .. nQuads−1), then the triangles (cage triangles and the
//                           triangles round each n-gon's centre)
//                edgeOwner  1 per edge: patch · 4 + local edge (the patch that measures it)
//                patternIJ  1 per pattern vertex: i | j << 16 (src/pattern/pow2.ts packPatterns)
//                patternIdx the patterns' local indices (the headless pass reads them)
//                entries    4 per pattern (domain · 7 + log2 L): baseVertex, firstIndex,
//                           indexCount, vertexCount
//   cageBuf    f32 (INST_CAGE of src/gpu/instanced/buffer-layouts.ts, its offsets in params):
//              cage positions, then unit vertex normals, 3 per vertex, then the Phong
//              surface's α of each prepared triangle's three edges (src/gpu/surface/phong.ts)
//
// The surface contract is the compute tessellator's (wgsl/tess/common.wgsl): evalSurface gets a
// cage triangle of prepare.ts and 16.16 barycentric weights in its corner order, and may call
// triVert, cagePos, cageNormal, phongAlpha and use PHONG_ALPHA and SurfacePoint, all defined here
// over this tessellator's own buffers. The exact Catmull-Clark and ACC surfaces plug in the same
// way: their module is appended instead of wgsl/surface/phong.wgsl, with whatever accessors it reads
// (its control points, quadtree nodes) bound and defined next to these (see src/gpu/instanced/instanced-options.ts
// InstancedOptions.surfaceWgsl). A quad patch's (u,v) maps to its two cage triangles exactly as
// src/gpu/tess/face-params.ts inverts it, so those surfaces see the same face parameter.

// The bindings (params, staticBuf, cageBuf, and the rest of group 0 per module) are declared in
// src/gpu/instanced/buffer-layouts.ts (INST_DRAW_MESH_GROUP, INST_LEVELS_GROUP) and generated.

// ONE (the 16.16 unit), PHONG_ALPHA, PATCH_WORDS, LEVELS (the pattern levels 1, 2, 4, …) and MAX_LEVEL (the largest)
// are generated from their TypeScript values (src/gpu/instanced/levels.ts).

struct SurfacePoint { pos: vec3<f32>, normal: vec3<f32>, du: vec3<f32>, dv: vec3<f32> } // as wgsl/tess/common.wgsl
// What the factor rule reads at a cage vertex (wgsl/instanced/levels.wgsl edgeFactorRule; each
// surface module's factorPoint).
struct FactorPoint { pos: vec3<f32>, normal: vec3<f32> }

fn triVert(t: u32, i: u32) -> u32 { return staticBuf[params.offTriVerts + 3u * t + i]; }
fn cageVec3(o: u32) -> vec3<f32> { return vec3<f32>(cageBuf[o], cageBuf[o + 1u], cageBuf[o + 2u]); }
fn cagePos(v: u32) -> vec3<f32> { return cageVec3(params.offPositions + 3u * v); }
fn cageNormal(v: u32) -> vec3<f32> { return cageVec3(params.offNormals + 3u * v); }
fn phongAlpha(t: u32, i: u32) -> f32 { return cageBuf[params.offPhongAlpha + 3u * t + i]; }

fn patchWord(p: u32, w: u32) -> u32 { return staticBuf[params.offPatches + PATCH_WORDS * p + w]; }
fn patchIsTri(p: u32) -> bool { return (patchWord(p, 1u) & 1u) == 1u; }
fn patchCanonical(p: u32, k: u32) -> bool { return ((patchWord(p, 1u) >> (1u + k)) & 1u) == 1u; }
fn patchEdge(p: u32, k: u32) -> u32 { return patchWord(p, 2u + k); }
fn patchEdgeCount(p: u32) -> u32 { return select(4u, 3u, patchIsTri(p)); }

fn entryWord(domain: u32, lg: u32, w: u32) -> u32 { return staticBuf[params.offEntries + 4u * (domain * LEVELS + lg) + w]; }

// (i, j) of a level-P pattern → the cage triangle and its 16.16 barycentric weights (ONE / P is
// an integer for P ≤ 64, so every weight is exact). Quad: u ≥ v lies in triangle (c0, c1, c2)
// with w = (1−u, u−v, v), else in (c0, c2, c3) with w = (1−v, u, v−u). Triangle: w = (1−u−v, u, v).
struct PatchTriangle { t: u32, w: vec3<u32> }

fn patchTriangle(p: u32, P: u32, i: u32, j: u32) -> PatchTriangle {
  let s = ONE / P;
  let t0 = patchWord(p, 0u);
  if (patchIsTri(p)) { return PatchTriangle(t0, vec3<u32>((P - i - j) * s, i * s, j * s)); }
  if (i >= j) { return PatchTriangle(t0, vec3<u32>((P - i) * s, (i - j) * s, j * s)); }
  return PatchTriangle(t0 + 1u, vec3<u32>((P - j) * s, i * s, (j - i) * s));
}

// fn patchSurface(p: u32, P: u32, i: u32, j: u32) -> SurfacePoint, the surface at pattern point
// (i, j) of patch p at level P, comes with the surface: wgsl/instanced/surface-tri.wgsl (the
// evalSurface contract, through patchTriangle) or wgsl/instanced/surface-acc.wgsl (ACC patches).

// (i, j) of the point at parameter t (from corner k) on edge k of a level-P pattern
// (src/pattern/pow2.ts edgePoint).
fn edgePoint(isTri: bool, P: u32, k: u32, t: u32) -> vec2<u32> {
  if (isTri) {
    if (k == 0u) { return vec2<u32>(t, 0u); }
    if (k == 1u) { return vec2<u32>(P - t, t); }
    return vec2<u32>(0u, P - t);
  }
  if (k == 0u) { return vec2<u32>(t, 0u); }
  if (k == 1u) { return vec2<u32>(P, t); }
  if (k == 2u) { return vec2<u32>(P - t, P); }
  return vec2<u32>(0u, P - t);
}

fn log2Level(L: u32) -> u32 { return firstTrailingBit(L); }
