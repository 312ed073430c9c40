#!/bin/bash
# The pads alternated over rounds, with a build that has pad.diff applied (CANOPY_EXP_PAD). Run
# from the repository root:
#   results/frame-graph-check/lit-pass/placement/run.sh OUT
# The committed runs read a copy of hard-vs-pcf-60.toml in a temporary folder (see the README).
set -euo pipefail
out=$1
cfg=results/frame-graph-check/lit-pass/hard-vs-pcf-60.toml
for r in 1 2 3 4; do
 for pad in 0 4096 65536 1052672 2097152; do
  CANOPY_EXP_PAD=$pad build/canopy run $cfg --no-reference --images none --no-progress --out "$out/p$pad-$r" >/dev/null 2>&1 || echo fail $pad $r
 done
done
