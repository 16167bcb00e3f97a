// The vertex function's surface without displacement (wgsl/instanced/draw.wgsl instancedVertex):
// the surface module's patchSurface at the snapped pattern point. With displacement,
// wgsl/instanced/displace.wgsl defines vertexSurface instead.
fn vertexSurface(p: u32, P: u32, i: u32, j: u32) -> SurfacePoint { return patchSurface(p, P, i, j); }
