// The lending compute Tessellator's arenas for displacement (src/gpu/instanced/displace-vertex.ts), on
// the Phong and ACC surfaces (the Catmull-Clark surface's group 3 already binds them:
// wgsl/instanced/surface-cc.wgsl). Bindings 0–2 here; src/gpu/instanced/displace-vertex.ts moves them to
// 2–4 on ACC, whose patches and control points hold 0 and 1. Named as the Catmull-Clark surface's
// borrowed buffers, so one rename list (src/gpu/instanced/surface-cc.ts RENAMES) serves both.
//   ccParams  its Params (src/gpu/contract/tess.ts TESS_PARAMS: dispOn, dispScale, … and where its arrays lie)
//   ccStatic  its TESS_STATIC arena (triEdges, edgeOwner, vertexOwner, heightTexels, dispTri)
//   ccCage    its TESS_CAGE arena (cornerUvs)

@group(3) @binding(0) var<uniform> ccParams: Params;
@group(3) @binding(1) var<storage, read> ccStatic: array<u32>;
@group(3) @binding(2) var<storage, read> ccCage: array<f32>;
