#!/usr/bin/env bash
# Build tools/osd-check/osd_time.cpp (OpenSubdiv timing for `npm run bench`) with g++ against
# Debian's libosd-dev, into the gitignored .build/osd/ (or $OSD_TIME_BUILD). Prints the
# binary's path on stdout; rebuilds only when a source is newer than the binary. Exits
# non-zero (with the compiler's message on stderr) where g++ or libosd-dev is missing.
#   bash tools/osd-check/build-time.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="${OSD_TIME_BUILD:-$ROOT/.build/osd}"
BIN="$BUILD/osd_time"
SRC="$ROOT/tools/osd-check/osd_time.cpp"
HDR="$ROOT/tools/osd-check/obj_reader.h"
REF="$ROOT/tools/osd-check/refiner.h"
mkdir -p "$BUILD"
if [ ! -x "$BIN" ] || [ "$SRC" -nt "$BIN" ] || [ "$HDR" -nt "$BIN" ] || [ "$REF" -nt "$BIN" ]; then
  g++ -O2 -std=c++17 -o "$BIN.tmp" "$SRC" -losdCPU >&2
  mv "$BIN.tmp" "$BIN"
fi
echo "$BIN"
