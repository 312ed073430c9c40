#!/usr/bin/env bash
# `canopy report` in a real browser: a small paper run (tests/data/experiments/tiny_paper.toml)
# written with `canopy run --report`, opened in headless Chromium with #selftest. The page's own
# check (harness/report/report_page_assets.cpp) writes its verdict into the DOM, read back with
# --dump-dom: no script error, every image loaded, a wheel on one panel zooms its three
# neighbours, a click on "time ratio" sorts the results, and in a narrow window (760 px) no table
# cell lies beyond the page's width unless its table scrolls in its own box. Then a screenshot
# must come out.
# Usage: report_in_chromium.sh CANOPY DATA_DIR
# Exit 77 (ctest: skipped) only where Chromium is not installed; a Chromium that fails to start fails.
set -euo pipefail
canopy=$1
data=$2
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "SKIPPED: Chromium is not installed (scripts/install-deps installs Debian's chromium)"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$canopy" run "$data/experiments/tiny_paper.toml" --out "$work/run" --quick --no-progress --no-cache --report \
  >"$work/stdout" 2>"$work/stderr" || fail "canopy run --report failed: $(cat "$work/stderr")"
page="$work/run/report.html"
[ -s "$page" ] || fail "no report.html"
grep -q "report.html" "$work/stdout" || fail "canopy run does not name the report"
# Self-contained: no network reference, no external script or style.
! grep -Eq '<script[^>]+src=|<link[^>]+href=|https?://[a-z]' "$page" || fail "the page loads something from elsewhere"

# As root, Chromium needs --no-sandbox; a container's /dev/shm is small.
flags=(--headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run --hide-scrollbars
       --user-data-dir="$work/profile" --virtual-time-budget=20000)
timeout 120 "$browser" "${flags[@]}" --window-size=760,1000 --dump-dom "file://$page#selftest" >"$work/dom.html" 2>"$work/chromium.log" ||
  fail "Chromium failed (exit $?): $(tail -5 "$work/chromium.log")"
python3 - "$work/dom.html" <<'PY' || fail "the page's self-test failed"
import html, json, re, sys
dom = open(sys.argv[1], encoding="utf-8").read()
m = re.search(r'<pre id="selftest-result">(.*?)</pre>', dom, re.S)
if not m or not m.group(1).strip():
    sys.exit("the self-test wrote no verdict (did the page's script run?)")
result = json.loads(html.unescape(m.group(1)))
print("self-test:", json.dumps(result))
problems = []
if result["errors"]: problems.append(f"script errors: {result['errors']}")
if result["broken"]: problems.append(f"images that did not load: {result['broken']}")
# 3 cases x 4 panels (technique, reference, error, FLIP)
if result["images"] < 12: problems.append(f"only {result['images']} images")
if result["zoom_synchronised"] is not True: problems.append("zooming one panel did not zoom its neighbours")
if result["sortable"] is not True: problems.append("the results table did not sort by time ratio")
if result.get("tables_fit") is not True:
    problems.append(f"tables cut off at the page's edge: {result.get('cut_off')}, widths {result.get('page_width')}")
if not result["pass"]: problems.append("the page says fail")
for needle in ("Pareto fronts", "Paper comparison", "TEST-T1", "Environment", "PCF 5x5 is slower than hard shadows"):
    if needle not in dom: problems.append(f"the page lacks '{needle}'")
if problems: sys.exit("; ".join(problems))
PY

timeout 120 "$browser" "${flags[@]}" --window-size=1400,1800 --screenshot="$work/shot.png" "file://$page" \
  >"$work/shot.log" 2>&1 || fail "Chromium's screenshot failed: $(tail -5 "$work/shot.log")"
python3 - "$work/shot.png" <<'PY' || fail "the screenshot is not a 1400x1800 PNG"
import struct, sys
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
width, height = struct.unpack(">II", data[16:24])
assert (width, height) == (1400, 1800), (width, height)
assert len(data) > 20000, f"{len(data)} bytes: an empty page?"
PY
echo "report: self-test passed, screenshot taken"
