#!/usr/bin/env bash
# On the GPU machine, from the repository root, with .gpubench/ (bench/gpu/pack.sh) beside it:
# `npm run bench` and both `npm run bench:instanced` runs through the packed Node and Dawn, into
# $OUT (bench-gpu.md, inst.md, inst-cc.md and their logs). Then, back here,
# `node bench/gpu/merge.mjs DIR` puts them into BENCHMARKS.md's real-GPU section.
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
for s in ${STEPS:-bench inst inst-cc}; do
  t0=$(date +%s)
  case $s in
    bench) "$G/node" "$G/dist/bench.mjs" ${BENCH_ARGS:-} --out "$OUT/bench-gpu.md" >"$OUT/bench.log" 2>&1 ;;
    inst) "$G/node" "$G/dist/instanced.mjs" --level 16 --out "$OUT/inst.md" >"$OUT/inst.log" 2>&1 ;;
    inst-cc) "$G/node" "$G/dist/instanced.mjs" --level 16 --surface catmull-clark --out "$OUT/inst-cc.md" >"$OUT/inst-cc.log" 2>&1 ;;
  esac
  echo "== $s rc=$? $(($(date +%s) - t0)) s"
  tail -3 "$OUT/$s.log"
done
