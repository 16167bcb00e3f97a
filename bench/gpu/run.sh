#!/usr/bin/env bash
# On the GPU machine, from the repository root, with .gpubench/ (bench/gpu/pack.sh) beside it:
# `npm run bench`, both `npm run bench:instanced` runs and scripts/acc-errors.ts, through the packed
# Node and Dawn, into $OUT: bench-gpu.md, inst.md, inst-cc.md, acc.md, gpu.txt and one run.log (the
# device tool brings back at most 8 files). Then, back here, `node bench/gpu/merge.mjs DIR` puts them
# into BENCHMARKS.md's real-GPU section.
# A Vulkan loader must be on the machine (or unpacked from .deb files in .gl/ first).
set -u
OUT=${OUT:-/tmp/gpubench-out}; mkdir -p "$OUT"
if [ -d .gl ]; then for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig; fi
ICD=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
[ -f "$ICD" ] && export VK_DRIVER_FILES=$ICD
G=$PWD/.gpubench
[ -x "$G/node" ] || { xz -dc "$G/node.xz" >"$G/node" && chmod +x "$G/node"; }
D=$G/node_modules/webgpu/dist/linux-x64
[ -f "$D/dawn.node" ] || xz -dc "$D/dawn.node.xz" >"$D/dawn.node"
# The talk's cages where ../shared is absent (the benchmark reads ../shared/cages).
if [ ! -d ../shared/cages ] && ls "$G"/cages/*.obj >/dev/null 2>&1; then mkdir -p ../shared/cages && cp "$G"/cages/*.obj ../shared/cages/; fi
# OpenSubdiv's timing tool, prebuilt (no compiler or libosd-dev there); touched so it counts as fresh.
if [ -x "$G/lib/osd_time" ]; then
  mkdir -p .build/osd && cp "$G/lib/osd_time" .build/osd/osd_time && touch .build/osd/osd_time
  export LD_LIBRARY_PATH=$G/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
fi
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv 2>&1 | tee "$OUT/gpu.txt"
echo >"$OUT/run.log"
for s in ${STEPS:-bench inst inst-cc acc}; do
  t0=$(date +%s)
  case $s in
    bench) "$G/node" "$G/dist/bench.mjs" ${BENCH_ARGS:-} --out "$OUT/bench-gpu.md" >>"$OUT/run.log" 2>&1 ;;
    inst) "$G/node" "$G/dist/instanced.mjs" --level 16 --out "$OUT/inst.md" >>"$OUT/run.log" 2>&1 ;;
    inst-cc) "$G/node" "$G/dist/instanced.mjs" --level 16 --surface catmull-clark --out "$OUT/inst-cc.md" >>"$OUT/run.log" 2>&1 ;;
    # The ACC error table with its GPU build column (it prints the table; errors are CPU, f64:
    # imrod's exact reference alone takes minutes, so ACC_ARGS=--only=... may leave it out).
    acc) timeout "${ACC_TIMEOUT:-300}" "$G/node" "$G/dist/acc-errors.mjs" ${ACC_ARGS:-} | tee -a "$OUT/run.log" | grep '^|' >"$OUT/acc.md" ;;
  esac
  echo "== $s rc=${PIPESTATUS[0]} $(($(date +%s) - t0)) s" | tee -a "$OUT/run.log"
done
tail -3 "$OUT/run.log"
