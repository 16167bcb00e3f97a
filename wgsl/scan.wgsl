// Exclusive prefix sum of n u32 values inside the `work` buffer, reduce-then-scan in three
// direct dispatches (WebGPU gives no forward-progress guarantee, so no single-pass lookback):
//   scanBlocks   each workgroup scans 256 values and writes its block total
//   scanSums     one workgroup scans the block totals (≤ 65535 of them) and writes the grand
//                total at out[n]
//   addSums      adds each block's offset
// Up to 65535·256 ≈ 16.7M values.

struct ScanParams { inOff: u32, outOff: u32, n: u32, sumsOff: u32 }

@group(0) @binding(0) var<uniform> scan: ScanParams;
@group(0) @binding(1) var<storage, read_write> work: array<u32>;

const BLOCK: u32 = 256u;
var<workgroup> partial: array<u32, 256>;

// Inclusive Hillis-Steele scan of `partial` across the workgroup.
fn scanShared(lid: u32) {
  for (var step = 1u; step < BLOCK; step = step << 1u) {
    workgroupBarrier();
    let add = select(0u, partial[lid - step], lid >= step);
    workgroupBarrier();
    partial[lid] += add;
  }
  workgroupBarrier();
}

@compute @workgroup_size(256)
fn scanBlocks(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let i = wid.x * BLOCK + lid;
  let v = select(0u, work[scan.inOff + i], i < scan.n);
  partial[lid] = v;
  scanShared(lid);
  if (i < scan.n) { work[scan.outOff + i] = partial[lid] - v; }
  if (lid == BLOCK - 1u) { work[scan.sumsOff + wid.x] = partial[lid]; }
}

@compute @workgroup_size(256)
fn scanSums(@builtin(local_invocation_index) lid: u32) {
  let blocks = (scan.n + BLOCK - 1u) / BLOCK;
  let per = (blocks + BLOCK - 1u) / BLOCK;
  let first = lid * per;
  var total = 0u;
  for (var k = 0u; k < per; k++) {
    if (first + k < blocks) { total += work[scan.sumsOff + first + k]; }
  }
  partial[lid] = total;
  scanShared(lid);
  var run = partial[lid] - total;
  for (var k = 0u; k < per; k++) {
    if (first + k < blocks) {
      let s = work[scan.sumsOff + first + k];
      work[scan.sumsOff + first + k] = run;
      run += s;
    }
  }
  if (lid == BLOCK - 1u) { work[scan.outOff + scan.n] = partial[lid]; }
}

@compute @workgroup_size(256)
fn addSums(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  let i = wid.x * BLOCK + lid;
  if (i < scan.n) { work[scan.outOff + i] += work[scan.sumsOff + wid.x]; }
}
