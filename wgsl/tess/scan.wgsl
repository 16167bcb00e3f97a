// The counts' exclusive prefix sums and the budget, in two dispatches whatever the camera
// (reduce-then-scan: WebGPU gives no forward-progress guarantee, so no single-pass lookback).
// The factor and count passes have written every count at every budget candidate
// (contract/tess.ts BUDGET_SCALES), SCANS lanes per candidate (TESS_SCANS, scanLane* below):
//   scanReduce   every lane at once (workgroup y = lane): each workgroup sums one block of
//                BLOCK = SCAN_WORKGROUP_SIZE × SCAN_ITEMS (128 × 32) values (32 consecutive ones
//                per thread, summed serially, so a big count needs few workgroups and barriers)
//   scanDown     the chosen candidate's lanes only (workgroup y = lane kind). Every workgroup
//                first makes the budget's choice itself, from every lane's block sums: totals
//                each candidate's output vertices and triangles and takes the first candidate
//                that fits the output buffers. The block sums are few (one per 4096 counts) and
//                every workgroup reads the same ones, so all choose alike, and the choice needs
//                no dispatch of its own (a dispatch is a launch and a barrier on a GPU). One
//                workgroup writes the draw and dispatch arguments from the chosen totals. Then
//                each block's own exclusive scan plus its block's offset (the sum of its lane's
//                earlier blocks), into the prefix-sum arrays; and the edges' factors, states
//                and segments at the chosen candidate (common.wgsl)
// Up to 65535 blocks of 4096 values a lane. Totals that do not fit in 32 bits (a large cage at
// scale 1) saturate, so they read as "does not fit" rather than wrapping to a small number; the
// chosen candidate's totals fit the output buffers, so its sums are exact.

const THREADS: u32 = SCAN_WORKGROUP_SIZE;
const ITEMS: u32 = SCAN_ITEMS;
const BLOCK: u32 = THREADS * ITEMS;
const SATURATED: u32 = 0xffffffffu;
var<workgroup> partial: array<u32, THREADS>;
var<workgroup> chosen: u32;

fn addSaturating(a: u32, b: u32) -> u32 {
  let s = a + b;
  return select(s, SATURATED, s < a);
}

// Words of one lane's block sums (src/gpu/contract/tess.ts scanSumsWords of the longer array).
fn sumsStride() -> u32 { return (max(max(params.nEdges, params.nTris), 1u) + BLOCK - 1u) / BLOCK + 1u; }
fn laneSums(lane: u32) -> u32 { return params.offSums + lane * sumsStride(); }
fn laneBlocks(kind: u32) -> u32 { return (scanLaneLength(kind) + BLOCK - 1u) / BLOCK; }

// Inclusive Hillis-Steele scan of `partial` across the workgroup.
fn scanPartial(lid: u32) {
  for (var step = 1u; step < THREADS; step = step << 1u) {
    workgroupBarrier();
    let add = select(0u, partial[lid - step], lid >= step);
    workgroupBarrier();
    partial[lid] = addSaturating(partial[lid], add);
  }
  workgroupBarrier();
}

@compute @workgroup_size(THREADS)
fn scanReduce(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let lane = wid.y;
  let kind = lane % SCANS;
  let n = scanLaneLength(kind);
  if (wid.x * BLOCK >= n) { return; } // uniform: this lane has fewer blocks than the longest
  let input = scanLaneIn(kind) + (lane / SCANS) * n;
  let first = wid.x * BLOCK + lid * ITEMS;
  var sum = 0u;
  for (var k = 0u; k < ITEMS; k++) {
    if (first + k < n) { sum = addSaturating(sum, work[input + first + k]); }
  }
  partial[lid] = sum;
  scanPartial(lid);
  if (lid == THREADS - 1u) { work[laneSums(lane) + wid.x] = partial[lid]; }
}

// The emit pass's indirect dispatch arguments, folded into 2D.
fn dispatchArgs(threads: u32) -> vec3<u32> {
  let groups = (threads + WORKGROUP_SIZE - 1u) / WORKGROUP_SIZE;
  if (groups == 0u) { return vec3<u32>(0u, 1u, 1u); }
  return vec3<u32>(min(groups, GRID_X), (groups + GRID_X - 1u) / GRID_X, 1u);
}

// Every lane's total, by the whole workgroup: thread t sums every PER_LANE-th block sum of lane
// t % LANES (from block t / LANES), then LANES threads add up their lane's PER_LANE partials.
const LANES: u32 = SCANS * BUDGET_CANDIDATES;
const PER_LANE: u32 = THREADS / LANES;
const_assert THREADS % (SCANS * BUDGET_CANDIDATES) == 0u;
var<workgroup> laneTotal: array<u32, SCANS * BUDGET_CANDIDATES>;

fn laneTotals(lid: u32) {
  let lane = lid % LANES;
  let blocks = laneBlocks(lane % SCANS);
  var sum = 0u;
  for (var b = lid / LANES; b < blocks; b += PER_LANE) { sum = addSaturating(sum, work[laneSums(lane) + b]); }
  partial[lid] = sum;
  workgroupBarrier();
  if (lid < LANES) {
    var total = 0u;
    for (var k = 0u; k < PER_LANE; k++) { total = addSaturating(total, partial[lid + k * LANES]); }
    laneTotal[lid] = total;
  }
  workgroupBarrier();
}

// The budget's choice (thread 0, from laneTotal): the first candidate whose vertices and
// triangles fit the output buffers, else the last (factor 1 everywhere, which setMesh checks
// always fits).
fn chooseCandidate() -> u32 {
  var c = 0u;
  loop {
    if (candidateFits(c) || c == BUDGET_CANDIDATES - 1u) { break; }
    c++;
  }
  return c;
}

// Lanes of candidate c: edge points, interior vertices, triangles, rows (TESS_SCANS).
fn candidateVertices(c: u32) -> u32 { return addSaturating(params.nSlots, addSaturating(laneTotal[SCANS * c], laneTotal[SCANS * c + 1u])); }
fn candidateFits(c: u32) -> bool {
  return candidateVertices(c) <= params.vertexCapacity && laneTotal[SCANS * c + 2u] <= params.triangleCapacity;
}

// The budget's outputs (one thread of one workgroup): its state, the chosen candidate's grand
// totals (at n of each prefix-sum array; scanDown writes the rest), the draw arguments, the
// counts the page reads, and the emit pass's indirect dispatch. Nothing overflows and nothing is
// lost at any camera: the plan and emit passes only run when the chosen candidate fits.
fn writeBudget(c: u32) {
  let vertices = candidateVertices(c);
  let triangles = laneTotal[SCANS * c + 2u];
  let fits = candidateFits(c);
  let b = params.offBudget;
  work[b + BUDGET_ACCEPTED] = 1u;
  work[b + BUDGET_CANDIDATE] = c;
  work[b + BUDGET_FITS] = select(0u, 1u, fits);
  work[b + BUDGET_SCALE] = bitcast<u32>(BUDGET_SCALES[c]);
  for (var kind = 0u; kind < SCANS; kind++) { work[scanLaneOut(kind) + scanLaneLength(kind)] = laneTotal[SCANS * c + kind]; }
  let shown = select(0u, triangles, fits);
  drawArgs = array(3u * shown, 1u, 0u, 0u, 0u);
  counts = array(select(0u, vertices, fits), shown, bitcast<u32>(BUDGET_SCALES[c]), c);
  // One emit thread per output vertex (the welded ones included); the triangles' emit is a
  // workgroup per cage triangle (wgsl/tess/emit.wgsl `triangles`), sized on the CPU.
  // (and a thread per extra sector slot for its position: wgsl/tess/weld.wgsl)
  let v = dispatchArgs(select(0u, vertices + params.nSlots - params.nVerts, fits));
  emitArgs = array(v.x, v.y, v.z);
}

// The sum of lane `lane`'s block sums before block `block`, by the whole workgroup.
fn blockOffset(lane: u32, block: u32, lid: u32) -> u32 {
  var sum = 0u;
  for (var b = lid; b < block; b += THREADS) { sum = addSaturating(sum, work[laneSums(lane) + b]); }
  partial[lid] = sum;
  scanPartial(lid);
  let all = partial[THREADS - 1u];
  workgroupBarrier(); // before the block's own scan reuses `partial`
  return all;
}

@compute @workgroup_size(THREADS)
fn scanDown(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  laneTotals(lid);
  if (lid == 0u) {
    chosen = chooseCandidate();
    if (wid.x == 0u && wid.y == 0u) { writeBudget(chosen); }
  }
  let c = workgroupUniformLoad(&chosen);
  let kind = wid.y;
  let n = scanLaneLength(kind);
  if (wid.x * BLOCK >= n) { return; } // uniform
  let lane = SCANS * c + kind;
  let offset = blockOffset(lane, wid.x, lid);
  let input = scanLaneIn(kind) + c * n;
  let output = scanLaneOut(kind);
  let first = wid.x * BLOCK + lid * ITEMS;
  var sum = 0u;
  for (var k = 0u; k < ITEMS; k++) {
    if (first + k < n) { sum = addSaturating(sum, work[input + first + k]); }
  }
  partial[lid] = sum;
  scanPartial(lid);
  var run = addSaturating(offset, partial[lid] - sum);
  for (var k = 0u; k < ITEMS; k++) {
    let i = first + k;
    if (i < n) {
      work[output + i] = run;
      run = addSaturating(run, work[input + i]);
      // The edges' lines at the chosen candidate, where the weld, plan and emit read them
      // (TESS_SCANS: lane kind 0 is the edges').
      if (kind == 0u) {
        let l = edgeAtCandidate(bitcast<f32>(work[params.offEdgeFactor + i]), c);
        work[params.offEdgeF + i] = l.x;
        work[params.offEdgeState + i] = l.y;
        work[params.offEdgeSegs + i] = l.z;
      }
    }
  }
}
