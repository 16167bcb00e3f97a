// Pass 3 of each budget attempt, one thread: do the counts fit the output buffers? If so,
// accept them and write the indirect draw arguments; if not, pick the scale for the next
// attempt (src/gpu/tess/factors.ts budgetScale), and after that, factor 1 everywhere. Nothing
// overflows and nothing is lost at any camera: the emit passes only run once accepted.

// Indirect dispatch arguments of the emit passes (vertices, triangles) and of the weld's edge
// points, folded into 2D.
fn dispatchArgs(threads: u32) -> vec3<u32> {
  let groups = (threads + WORKGROUP_SIZE - 1u) / WORKGROUP_SIZE;
  if (groups == 0u) { return vec3<u32>(0u, 1u, 1u); }
  return vec3<u32>(min(groups, GRID_X), (groups + GRID_X - 1u) / GRID_X, 1u);
}

// One thread on purpose: one decision per budget attempt over a few totals, no work to spread.
@compute @workgroup_size(1)
fn main() {
  let b = params.offBudget;
  if (work[b + BUDGET_ACCEPTED] != 0u) { return; }
  let attempt = work[b + BUDGET_ATTEMPT];
  let vertices = params.nSlots + work[params.offEdgeBase + params.nEdges] + work[params.offTriVertBase + params.nTris];
  let triangles = work[params.offTriTriBase + params.nTris];
  let fits = vertices <= params.vertexCapacity && triangles <= params.triangleCapacity;
  if (fits || attempt >= ATTEMPTS - 1u) {
    work[b + BUDGET_ACCEPTED] = 1u;
    work[b + BUDGET_FITS] = select(0u, 1u, fits);
    let shown = select(0u, triangles, fits);
    drawArgs = array(3u * shown, 1u, 0u, 0u, 0u);
    var scale = 1.0;
    if (attempt == 1u) { scale = bitcast<f32>(work[b + BUDGET_SCALE]); }
    if (attempt >= ATTEMPTS - 1u) { scale = 0.0; }
    counts = array(select(0u, vertices, fits), shown, bitcast<u32>(scale), attempt);
    let v = dispatchArgs(select(0u, work[params.offTriVertBase + params.nTris], fits));
    let t = dispatchArgs(shown);
    let e = dispatchArgs(select(0u, work[params.offEdgeBase + params.nEdges], fits));
    emitArgs = array(v.x, v.y, v.z, t.x, t.y, t.z, e.x, e.y, e.z);
    return;
  }
  let ratio = min(f32(params.vertexCapacity) / f32(vertices), f32(params.triangleCapacity) / f32(triangles));
  work[b + BUDGET_SCALE] = bitcast<u32>(0.9 * sqrt(ratio));
  work[b + BUDGET_ATTEMPT] = attempt + 1u;
}
