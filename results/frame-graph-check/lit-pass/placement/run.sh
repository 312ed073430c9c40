#!/bin/bash
# alternate pads over rounds
cd /work/main
for r in 1 2 3 4; do
 for pad in 0 4096 65536 1052672 2097152; do
  CANOPY_EXP_PAD=$pad ./build/canopy run /tmp/padexp/exp.toml --no-reference --images none --no-progress --out /tmp/padexp/p$pad-$r >/dev/null 2>&1 || echo fail $pad $r
 done
done
