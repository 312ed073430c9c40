#!/bin/bash
# hard-vs-pcf-60 with LP_NUM_THREADS=0 (llvmpipe rasterizes on lavapipe's queue thread, so no
# pass waits on a hand-off between threads), both builds alternately. Run from the repository
# root with the build in build/:
#   results/frame-graph-check/lit-pass/single-thread/run.sh OLD_CHECKOUT OUT PAIRS
# OLD_CHECKOUT: a clean checkout of 9422dc5 built Release, with this config copied to the same
# path in it (its scene path resolves to that checkout's spheres.toml, unchanged since).
set -euo pipefail
old=$1; out=$(realpath -m "$2"); pairs=$3
cfg=results/frame-graph-check/lit-pass/hard-vs-pcf-60.toml
for k in $(seq 1 "$pairs"); do
  (cd "$old" && LP_NUM_THREADS=0 build/canopy run $cfg --no-reference --images none --no-progress --out "$out/before-$k" >/dev/null)
  LP_NUM_THREADS=0 build/canopy run $cfg --no-reference --images none --no-progress --out "$out/after-$k" >/dev/null
done
