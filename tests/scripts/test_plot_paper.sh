#!/usr/bin/env bash
# scripts/plot-paper: from a paper.json (as `canopy run` writes it) and a `canopy bench scaling`
# table, the plots of a reproduced table come out as PNG and SVG, without dates (reproducible),
# the error-by-column plot only where the columns are numbers; a folder without paper.json is
# refused with what to run. Skipped (77) only where Debian's matplotlib is not installed.
set -euo pipefail
script=$1
/usr/bin/python3 -c "import matplotlib" 2>/dev/null || { echo "SKIPPED: python3-matplotlib is not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

write_paper() {  # folder columns-json
  mkdir -p "$1"
  /usr/bin/python3 - "$1/paper.json" "$2" <<'PY'
import json, sys
columns = json.loads(sys.argv[2])
def row(label, technique, paper, ratio, vis):
    n = len(columns)
    return {"label": label, "technique": technique, "pass": "", "params": {},
            "paper_values": [1.0] * n, "paper_ratio": [paper] * n,
            "canopy_ratio": [None if ratio is None else {"median": ratio, "low": ratio * 0.97, "high": ratio * 1.03}] * n,
            "canopy_ms": [{"median": 10 * (ratio or 1), "mad": 0.1}] * n, "case_ids": ["x"] * n,
            "errors": {"visibility_rmse": [vis * (1 + i) for i in range(n)], "penumbra_rmse": [vis / 2] * n,
                       "flip_mean": [0.02] * n}}
json.dump({"id": "T-1", "title": "A test table", "source": "", "unit": "fps", "column_key": "scene",
           "columns": columns, "baseline": "hard", "experiment": "t", "device": "d", "quick": False, "rounds": 30,
           "rows": [row("hard", "shadow.hard", 1.0, 1.0, 0.08), row("PCF", "shadow.pcf", 1.5, 1.6, 0.05),
                    row("PCSS", "shadow.pcss", 2.0, None, 0.04)],
           "claims": []}, open(sys.argv[1], "w"))
PY
}
write_paper "$work/lights" '["light-0.4", "light-1.2", "light-2.4"]'
write_paper "$work/scenes" '["spheres", "car"]'
cat > "$work/kernel-scaling.md" <<'MD'
| technique | swept | passes timed | fitted p | expected | R² | a (ms) | widths: median ms |
|---|---|---|---:|---:|---:|---:|---|
| shadow.pcf | kernel | lit | 2.00 | 2 | 1.000 | 6.94 | 1: 8.04, 3: 16.35, 5: 33.11, 7: 58.52 |
| shadow.vsm | filter | prefilter_x + prefilter_y | 1.02 | 1 | 1.000 | 21.18 | 3: 33.48, 7: 50.93, 11: 68.46 |
MD
"$script" "$work/lights" "$work/scenes" --kernel-scaling "$work/kernel-scaling.md" >"$work/out" || fail "plot-paper failed"
for f in lights/plots/time-ratio lights/plots/error-vs-time lights/plots/error-by-light-size scenes/plots/time-ratio \
         scenes/plots/error-vs-time kernel-scaling; do
  for ext in png svg; do
    [ -s "$work/$f.$ext" ] || fail "missing $f.$ext"
    grep -q "$f.$ext" "$work/out" || fail "$f.$ext not listed"
  done
  head -c 8 "$work/$f.png" | od -c | grep -q "P   N   G" || fail "$f.png is not a PNG"
  ! grep -q "<dc:date>" "$work/$f.svg" || fail "$f.svg records a date"
done
[ ! -e "$work/scenes/plots/error-by-scene.png" ] || fail "an error-by-column plot for columns that are not numbers"
# The same input draws the same bytes.
md5sum "$work"/lights/plots/* > "$work/first"
"$script" "$work/lights" >/dev/null
md5sum "$work"/lights/plots/* | diff -q - "$work/first" >/dev/null || fail "a second run drew other bytes"
# A run without a [paper] table (its config is not in the checkout): error against time per group.
mkdir -p "$work/grass"
/usr/bin/python3 - "$work/grass/results.json" <<'PY'
import json, sys
def case(cid, technique, ratio, flip):
    return {"id": cid, "technique": technique, "ok": True, "image_error": {"flip_mean": flip},
            "ratio": {"median": ratio, "ci95_low": ratio * 0.95, "ci95_high": ratio * 1.05}}
cases = [case("n-blades", "grass.geometry", 1.0, 0.02), case("n-volume", "grass.volume", 0.2, 0.05),
         case("f-blades", "grass.geometry", 1.0, 0.03), case("f-image", "grass.image", 0.01, 0.06)]
json.dump({"experiment": "grass-test", "config": "configs/no-such-experiment.toml", "cases": cases,
           "groups": [{"name": "near 64x36", "cases": ["n-blades", "n-volume"]},
                      {"name": "far 64x36", "cases": ["f-blades", "f-image"]}]}, open(sys.argv[1], "w"))
PY
"$script" "$work/grass" >"$work/out" || fail "plot-paper failed on a run without a paper table"
[ -s "$work/grass/plots/error-vs-time.png" ] && [ -s "$work/grass/plots/error-vs-time.svg" ] || fail "no error-vs-time for a run"
# A folder with neither paper.json nor results.json.
mkdir -p "$work/empty"
if "$script" "$work/empty" 2>"$work/err"; then fail "a folder without paper.json was accepted"; fi
grep -q "canopy export-paper" "$work/err" || fail "the refusal does not say how to make paper.json: $(cat "$work/err")"
echo "plot-paper: ok"
