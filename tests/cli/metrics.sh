#!/usr/bin/env bash
# `canopy metrics` lists every registered error metric (harness/metrics/metric_registry.cpp) with
# its compare tolerance; `canopy --help` names the command. Usage: metrics.sh CANOPY
set -uo pipefail
canopy=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$canopy" metrics >"$work/metrics" 2>&1 || fail "canopy metrics failed: $(cat "$work/metrics")"
cat "$work/metrics"
for name in rmse psnr_db flip_mean light_bleeding visibility_rmse visibility_excluded; do
  grep -q "^| $name " "$work/metrics" || fail "canopy metrics lacks $name"
done
grep -q "0.02 + 0 x abs(baseline)" "$work/metrics" || fail "canopy metrics lacks PSNR's compare tolerance"
"$canopy" --help >"$work/help" 2>&1 && grep -q "metrics" "$work/help" || fail "--help lists no metrics command"
