#!/bin/bash
# The quick suite timed with both builds, alternately: before-k (9422dc5, the last renderer
# without the frame graph), then after-k (the current build). Timing only (no reference, no
# images). Run from the repository root with the build in build/:
#   results/frame-graph-check/absolute/run.sh OLD_CHECKOUT OUT PAIRS
# OLD_CHECKOUT: a clean checkout of 9422dc5 built Release (scripts/build). Nothing else may load
# the machine meanwhile. Then: results/frame-graph-check/absolute_times.py 'OUT/before-*' 'OUT/after-*'
set -euo pipefail
old=$1; out=$(realpath -m "$2"); pairs=$3
cfg=configs/experiments/quick-suite.toml
for k in $(seq 1 "$pairs"); do
  (cd "$old" && build/canopy run $cfg --no-reference --images none --no-progress --out "$out/before-$k" >/dev/null)
  build/canopy run $cfg --no-reference --images none --no-progress --out "$out/after-$k" >/dev/null
done
