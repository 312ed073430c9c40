#!/usr/bin/env bash
# scripts/device-ratios merges the ratio tables of two runs' paper.md by row and column, each
# run headed by its device, and ignores the tables after the first.
set -euo pipefail
script=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
write_run() {  # folder device ratio-of-B
  mkdir -p "$1"
  cat > "$1/paper.md" <<MD
# T-1 — A test table

canopy 0.1.0 on $2 (driver 1), nproc 2, commit abc; experiment x.

## Frame time relative to A (paper → **canopy**)

| row | 512 | 1024 |
|---|---:|---:|
| A | 1.00 → **1.00** [1.00, 1.00] | 1.00 → **1.00** [1.00, 1.00] |
| B | 2.50 → **$3** [1.90, 2.10] | 3.00 → **4.00** [3.90, 4.10] |

## Raw numbers (paper / canopy median ± MAD)

| row | 512 | 1024 |
|---|---:|---:|
| A | 9 fps / 1.0 ± 0.1 ms | 8 fps / 2.0 ± 0.1 ms |
MD
}
write_run "$work/cpu" "llvmpipe (LLVM 15)" 2.00
write_run "$work/gpu" "Some GPU" 1.25
out=$(python3 "$script" "$work/cpu" "$work/gpu")
echo "$out"
grep -qxF '| row | case | paper | llvmpipe | Some GPU |' <<<"$out"
grep -qxF '| B | 512 | 2.50 | 2.00 [1.90, 2.10] | 1.25 [1.90, 2.10] |' <<<"$out"
grep -qxF '| B | 1024 | 3.00 | 4.00 [3.90, 4.10] | 4.00 [3.90, 4.10] |' <<<"$out"
[ "$(grep -c "^| " <<<"$out")" -eq 5 ]  # the header and 2 rows x 2 columns: nothing from the raw table
echo "device-ratios: ok"
