// Exclusive prefix sum of n u32 values inside the `work` buffer, reduce-then-scan in three
// direct dispatches (WebGPU gives no forward-progress guarantee, so no single-pass lookback):
//   scanBlocks   each workgroup scans BLOCK = SCAN_WORKGROUP_SIZE × SCAN_ITEMS (128 × 32) values (32 consecutive ones per thread,
//                summed serially, so a big scan needs few workgroups and few barriers) and
//                writes its block total
//   scanSums     one workgroup scans the block totals and writes the grand total at out[n]
//   addSums      adds each block's offset
// Up to 65535 blocks of 4096 values. A scan whose `skipOff` word is non-zero does nothing: the
// budget loop's later attempts skip their scans once an attempt has been accepted.

// `scan: ScanParams`, `work` and the constants come from src/gpu/contract/contract.ts (scanPrelude).

const THREADS: u32 = SCAN_WORKGROUP_SIZE;
const ITEMS: u32 = SCAN_ITEMS;
const BLOCK: u32 = THREADS * ITEMS;
var<workgroup> partial: array<u32, THREADS>;
var<workgroup> skip: u32;

fn skipped(lid: u32) -> bool {
  if (lid == 0u) { skip = work[scan.skipOff]; }
  return workgroupUniformLoad(&skip) != 0u;
}

// Inclusive Hillis-Steele scan of `partial` across the workgroup.
fn scanPartial(lid: u32) {
  for (var step = 1u; step < THREADS; step = step << 1u) {
    workgroupBarrier();
    let add = select(0u, partial[lid - step], lid >= step);
    workgroupBarrier();
    partial[lid] += add;
  }
  workgroupBarrier();
}

@compute @workgroup_size(THREADS)
fn scanBlocks(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  if (skipped(lid)) { return; }
  let first = wid.x * BLOCK + lid * ITEMS;
  var sum = 0u;
  for (var k = 0u; k < ITEMS; k++) {
    if (first + k < scan.n) { sum += work[scan.inOff + first + k]; }
  }
  partial[lid] = sum;
  scanPartial(lid);
  var run = partial[lid] - sum;
  for (var k = 0u; k < ITEMS; k++) {
    if (first + k < scan.n) {
      let v = work[scan.inOff + first + k];
      work[scan.outOff + first + k] = run;
      run += v;
    }
  }
  if (lid == THREADS - 1u) { work[scan.sumsOff + wid.x] = partial[lid]; }
}

@compute @workgroup_size(THREADS)
fn scanSums(@builtin(local_invocation_index) lid: u32) {
  if (skipped(lid)) { return; }
  let blocks = (scan.n + BLOCK - 1u) / BLOCK;
  let per = (blocks + THREADS - 1u) / THREADS;
  let first = lid * per;
  var total = 0u;
  for (var k = 0u; k < per; k++) {
    if (first + k < blocks) { total += work[scan.sumsOff + first + k]; }
  }
  partial[lid] = total;
  scanPartial(lid);
  var run = partial[lid] - total;
  for (var k = 0u; k < per; k++) {
    if (first + k < blocks) {
      let s = work[scan.sumsOff + first + k];
      work[scan.sumsOff + first + k] = run;
      run += s;
    }
  }
  if (lid == THREADS - 1u) { work[scan.outOff + scan.n] = partial[lid]; }
}

@compute @workgroup_size(THREADS)
fn addSums(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
  if (skipped(lid)) { return; }
  let first = wid.x * BLOCK + lid * ITEMS;
  let offset = work[scan.sumsOff + wid.x];
  for (var k = 0u; k < ITEMS; k++) {
    if (first + k < scan.n) { work[scan.outOff + first + k] += offset; }
  }
}
