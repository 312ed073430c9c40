#!/bin/bash
# As absolute/run.sh, with 9422dc5 given canopy's heap settings through GLIBC_TUNABLES (the values
# harness/run/heap_settings.cpp sets with mallopt), so that both builds allocate alike:
#   results/frame-graph-check/heap-matched/run.sh OLD_CHECKOUT OUT PAIRS
set -euo pipefail
old=$1; out=$(realpath -m "$2"); pairs=$3
cfg=configs/experiments/quick-suite.toml
tunables=glibc.malloc.trim_threshold=1073741824:glibc.malloc.mmap_threshold=33554432:glibc.malloc.top_pad=67108864
for k in $(seq 1 "$pairs"); do
  (cd "$old" && GLIBC_TUNABLES=$tunables build/canopy run $cfg --no-reference --images none --no-progress --out "$out/before-$k" >/dev/null)
  build/canopy run $cfg --no-reference --images none --no-progress --out "$out/after-$k" >/dev/null
done
