#!/usr/bin/env bash
# Command-line behaviour: exit codes, file:line errors, nothing written on bad input,
# interrupted runs keep what finished. Usage: test_cli.sh CANOPY DATA_DIR CASE
set -uo pipefail
canopy=$1 data=$2 case=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

expect_bad_input() {  # config, regex the message must match
    "$canopy" run "$data/experiments/$1" --out "$work/out" >"$work/stdout" 2>"$work/stderr"
    local rc=$?
    cat "$work/stderr"
    [ $rc -eq 2 ] || fail "exit code $rc, expected 2"
    grep -Eq "$2" "$work/stderr" || fail "message does not match '$2'"
    [ ! -e "$work/out" ] || fail "output folder was created for a bad config"
}

case $case in
  misspelled_key)    expect_bad_input misspelled_key.toml 'misspelled_key\.toml:4: .*repetitons.*' ;;
  unknown_technique) expect_bad_input unknown_technique.toml 'unknown_technique\.toml:6: .*shadow\.pfc' ;;
  out_of_range)      expect_bad_input out_of_range.toml 'out_of_range\.toml:(8|9): .*kernel' ;;
  missing_file)
    "$canopy" run "$work/nope.toml" --out "$work/out" 2>"$work/stderr"; rc=$?
    cat "$work/stderr"
    [ $rc -eq 2 ] || fail "exit code $rc, expected 2"
    grep -q "nope.toml" "$work/stderr" || fail "message does not name the file" ;;
  help)
    # Outputs go to files first: grep -q closing a pipe early would fail the pipeline.
    "$canopy" --help >"$work/help" && grep -q "run" "$work/help" || fail "--help lists no run command"
    "$canopy" run --help >"$work/help" && grep -q -- "--quick" "$work/help" || fail "run --help lists no --quick"
    "$canopy" list >"$work/list" || fail "list failed"
    for technique in shadow.hard shadow.pcf shadow.pcss shadow.ssss shadow.vsm shadow.esm shadow.gauss-cdf \
                     shadow.power-cdf shadow.evsm shadow.msm; do
      grep -q "^$technique\$" "$work/list" || fail "list lacks $technique"
    done
    grep -q "kernel" "$work/list" || fail "list lacks the kernel parameter"
    "$canopy" devices >"$work/devices" && grep -q "0:" "$work/devices" || fail "devices lists no device"
    # canopy graph: the declared frame graph, every pass with its uses; a misspelled name gets a suggestion.
    "$canopy" graph shadow.ssss >"$work/graph" || fail "graph shadow.ssss failed"
    grep -q "^pass frame raster shadow_map" "$work/graph" || fail "graph lacks the shadow_map pass"
    grep -q "^pass frame compute" "$work/graph" || fail "graph lacks SSSS's compute passes"
    grep -q "storage-write" "$work/graph" || fail "graph lacks the uses of the compute passes"
    "$canopy" graph shadow.pcs >"$work/graph" 2>&1; code=$?
    [ "$code" -eq 2 ] || fail "graph of an unknown technique exited $code, not 2"
    grep -q "did you mean 'shadow.pc" "$work/graph" || fail "graph of an unknown technique suggests nothing" ;;
  run)
    "$canopy" run "$data/experiments/tiny.toml" --out "$work/out" --quick --no-cache >"$work/stdout" 2>"$work/stderr" || fail "run failed: $(cat "$work/stderr")"
    cat "$work/stdout"
    for f in results.json results.csv results.md; do [ -s "$work/out/$f" ] || fail "missing $f"; done
    # canopy holds the heap still before the device starts (run/heap_settings.hpp) and says how;
    # under a sanitizer, whose allocator refuses mallopt, the record says that instead.
    heap=$(python3 -c "import json; print(json.load(open('$work/out/results.json'))['environment']['heap'])")
    case "$heap" in "glibc trim_threshold="*|"allocator defaults (mallopt refused)") ;; *) fail "environment.heap is '$heap'" ;; esac
    grep -q "^- heap while measuring: $heap" "$work/out/results.md" || fail "results.md does not name the heap settings"
    cases=$(ls "$work/out/images" | grep -v -e '^reference_' -e '\.error\.png$' -e '\.flip\.png$' -e '\.visibility\.exr$')
    [ "$(grep -c '\.png$' <<<"$cases")" -eq 3 ] || fail "expected 3 case PNGs"
    [ "$(grep -c '\.exr$' <<<"$cases")" -eq 3 ] || fail "expected 3 case EXRs"
    [ "$(ls "$work/out/images" | grep -v '^reference_' | grep -c '\.visibility\.exr$')" -eq 3 ] || fail "expected 3 case visibility EXRs"
    [ -s "$work/out/images/reference_tiny_96x64.png" ] || fail "missing the reference image"
    grep -q "shadow.hard" "$work/stdout" || fail "table lacks shadow.hard"
    grep -q "penumbra RMSE" "$work/stdout" || fail "table lacks the error columns"
    [ "$(ls "$work/out/images" | grep -c '\.flip\.png$')" -eq 3 ] || fail "expected 3 FLIP maps"
    "$canopy" run "$data/experiments/tiny.toml" --out "$work/plain" --quick --no-reference >"$work/stdout" 2>&1 || fail "run --no-reference failed"
    ! grep -q "penumbra RMSE" "$work/stdout" || fail "--no-reference still shows error columns" ;;
  runs)
    # --runs 5: four more runs, timing only, each its own process; paper.md's intervals then hold
    # this experiment's own spread between runs. Again: the finished runs are kept.
    "$canopy" run "$data/experiments/tiny_paper.toml" --out "$work/out" --quick --no-cache --images none --runs 5 \
      >"$work/stdout" 2>"$work/stderr" || fail "run --runs 5 failed: $(cat "$work/stderr")"
    cat "$work/stdout"
    for k in 2 3 4 5; do
      [ -s "$work/out/runs/run-$k/results.json" ] || fail "missing run $k"
      grep -q '"reference_enabled": false' "$work/out/runs/run-$k/results.json" || fail "run $k is not timing only"
    done
    grep -q "σ_run = .*this experiment's 5 runs" "$work/out/paper.md" || fail "paper.md does not take the spread from its own 5 runs"
    python3 -c "import json,sys; n=json.load(open('$work/out/paper.json'))['run_to_run_noise']; sys.exit(0 if n['sigma_log_ratio'] > 0 and '5 runs' in n['source'] else 1)" \
      || fail "paper.json names no spread of its own runs"
    before=$(stat -c %Y "$work/out/runs/run-3/results.json")
    "$canopy" run "$data/experiments/tiny_paper.toml" --out "$work/out" --quick --no-cache --images none --runs 5 --resume \
      >/dev/null 2>"$work/stderr2" || fail "resuming failed: $(cat "$work/stderr2")"
    [ "$(stat -c %Y "$work/out/runs/run-3/results.json")" = "$before" ] || fail "a finished run was measured again"
    "$canopy" run "$data/experiments/tiny_paper.toml" --out "$work/shard" --runs 2 --shard 1/2 2>"$work/stderr3"; rc=$?
    [ $rc -eq 2 ] || fail "--runs with --shard: exit $rc, expected 2" ;;
  reference)
    args=(--width 64 --height 48 --light-samples 8 --pixel-samples 1 --reference-cache "$work/cache" --out "$work/ref")
    "$canopy" reference "$data/scenes/tiny.toml" "${args[@]}" >"$work/first" || fail "reference failed"
    "$canopy" reference "$data/scenes/tiny.toml" "${args[@]}" >"$work/second" || fail "second reference failed"
    cat "$work/first" "$work/second"
    ! grep -q "from cache" "$work/first" || fail "first reference claims to come from the cache"
    grep -q "from cache" "$work/second" || fail "second reference was not taken from the cache"
    for f in tiny_64x48.exr tiny_64x48.png tiny_64x48.variance.exr tiny_64x48.visibility.exr tiny_64x48.pixel_visibility.exr; do
      [ -s "$work/ref/$f" ] || fail "missing $f"
    done
    # Another seed: an independent reference, not the cached one; image-error scores one against the other.
    "$canopy" reference "$data/scenes/tiny.toml" "${args[@]/$work\/ref/$work/ref2}" --seed 2 >"$work/third" || fail "seed 2 failed"
    ! grep "^reference " "$work/third" | grep -q "from cache" || fail "a reference of another seed came from the cache"
    "$canopy" image-error "$work/ref/tiny_64x48.exr" "$work/ref/tiny_64x48.exr" --json >"$work/same" || fail "image-error failed"
    grep -Eq '"mae": 0(\.0)?,?$' "$work/same" || fail "an image against itself: mae is not 0"
    "$canopy" image-error "$work/ref2/tiny_64x48.exr" "$work/ref/tiny_64x48.exr" --json >"$work/apart" || fail "image-error failed"
    ! grep -Eq '"mae": 0(\.0)?,?$' "$work/apart" || fail "two seeds' references are identical"
    "$canopy" reference "$data/scenes/tiny.toml" --width 32 --height 24 --light-samples 1 --pixel-samples 1 --no-cache --out "$work/small" >/dev/null || fail "small reference failed"
    "$canopy" image-error "$work/small/tiny_32x24.exr" "$work/ref/tiny_64x48.exr" 2>"$work/sizes"; rc=$?
    cat "$work/sizes"
    [ $rc -eq 2 ] || fail "images of two sizes: exit $rc, expected 2"
    grep -q "is 32x24, the reference 64x48" "$work/sizes" || fail "the size mismatch is not named" ;;
  bench)
    "$canopy" bench reference "$data/scenes/tiny.toml" --width 64 --height 48 --light-samples 4 --pixel-samples 1 >"$work/stdout" || fail "bench failed"
    cat "$work/stdout"
    grep -Eq "ratio reference / bare: [0-9.]+" "$work/stdout" || fail "bench prints no ratio"
    grep -q "bare rtcOccluded1 loop" "$work/stdout" || fail "bench prints no bare-loop row" ;;
  interrupt)
    # Many repetitions so the run is still going when SIGINT arrives.
    sed 's/repetitions = 3/repetitions = 100000/' "$data/experiments/tiny.toml" >"$work/long.toml"
    sed -i "s|\.\./scenes/|$data/scenes/|" "$work/long.toml"
    "$canopy" run "$work/long.toml" --out "$work/out" --no-progress >/dev/null 2>"$work/stderr" &
    pid=$!
    sleep 4
    kill -INT $pid
    wait $pid; rc=$?
    cat "$work/stderr"
    [ $rc -eq 130 ] || fail "exit code $rc, expected 130"
    python3 -c "import json,sys; j=json.load(open('$work/out/results.json')); sys.exit(0 if j['status']=='interrupted' else 1)" \
      || fail "results.json is not a valid interrupted record"
    ! ls -a "$work/out" | grep -q '\.tmp' || fail "temporary files left behind" ;;
  report_out)
    # Issue 36: `report --out /` wrote a temporary file at / and then failed with EBUSY.
    "$canopy" run "$data/experiments/tiny.toml" --out "$work/run" --quick --no-reference --images none --no-progress \
      >/dev/null 2>&1 || fail "run failed"
    before=$(ls -a / | sort)
    "$canopy" report "$work/run" --out / >"$work/stdout" 2>"$work/stderr"; rc=$?
    cat "$work/stderr"
    [ $rc -eq 2 ] || fail "report --out /: exit code $rc, expected 2"
    grep -q "^/: error: is the filesystem's root folder" "$work/stderr" || fail "report --out /: the message does not say why"
    [ "$(ls -a / | sort)" = "$before" ] || fail "report --out / wrote into /"
    "$canopy" compare "$work/run" "$work/run" --out / >/dev/null 2>"$work/stderr"; rc=$?
    [ $rc -eq 2 ] && grep -q "root folder" "$work/stderr" || fail "compare --out /: exit code $rc, expected 2"
    # A folder gets report.html (compare: compare.md); a new folder is created.
    mkdir "$work/pages"
    "$canopy" report "$work/run" --out "$work/pages" >/dev/null 2>"$work/stderr" || fail "report --out FOLDER: $(cat "$work/stderr")"
    [ -s "$work/pages/report.html" ] || fail "report --out FOLDER wrote no FOLDER/report.html"
    "$canopy" report "$work/run" --out "$work/new/sub/" >/dev/null 2>"$work/stderr" || fail "report --out NEW/: $(cat "$work/stderr")"
    [ -s "$work/new/sub/report.html" ] || fail "report --out NEW/ wrote no NEW/report.html"
    "$canopy" compare "$work/run" "$work/run" --out "$work/pages" >/dev/null 2>"$work/stderr" || fail "compare --out FOLDER: $(cat "$work/stderr")"
    grep -q "^# canopy compare" "$work/pages/compare.md" || fail "compare --out FOLDER wrote no FOLDER/compare.md"
    "$canopy" compare "$work/run" "$work/run" --out "$work/made/here/table.md" >/dev/null 2>"$work/stderr" \
      || fail "compare --out NEW/FILE: $(cat "$work/stderr")"
    [ -s "$work/made/here/table.md" ] || fail "compare did not create its folder"
    # Through a file: refused before anything is written.
    "$canopy" compare "$work/run" "$work/run" --out "$work/pages/report.html/table.md" >/dev/null 2>"$work/stderr"; rc=$?
    [ $rc -eq 2 ] && grep -q "report.html: error: is a file, not a folder" "$work/stderr" || fail "--out through a file: exit $rc" ;;
  compare_exit_codes)
    # Issue 36: compare exited 1 both for a regression and for a report it could not write.
    "$canopy" run "$data/experiments/tiny.toml" --out "$work/a" --quick --no-reference --images none --no-progress \
      >/dev/null 2>&1 || fail "run failed"
    cp -r "$work/a" "$work/b"
    python3 - "$work/b/results.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
j["cases"][1]["ok"] = False
j["cases"][1]["error"] = "made to fail by the test"
json.dump(j, open(sys.argv[1], "w"))
PY
    "$canopy" compare "$work/a" "$work/a" >/dev/null 2>&1; rc=$?
    [ $rc -eq 0 ] || fail "nothing flagged: exit $rc, expected 0"
    "$canopy" compare "$work/a" "$work/b" >/dev/null 2>&1; rc=$?
    [ $rc -eq 1 ] || fail "a case failed in the candidate: exit $rc, expected 1"
    "$canopy" compare "$work/a" "$work/missing" >/dev/null 2>&1; rc=$?
    [ $rc -eq 2 ] || fail "a missing run: exit $rc, expected 2"
    CANOPY_TEST_FAIL_WRITE_AFTER=0 "$canopy" compare "$work/a" "$work/a" --out "$work/table.md" >/dev/null 2>"$work/stderr"; rc=$?
    cat "$work/stderr"
    [ $rc -eq 3 ] || fail "a report that cannot be written: exit $rc, expected 3"
    grep -q "the report could not be written: cannot write .*table.md" "$work/stderr" || fail "the write failure is not named"
    CANOPY_TEST_FAIL_WRITE_AFTER=0 "$canopy" compare "$work/a" "$work/b" --out "$work/table.md" >/dev/null 2>&1; rc=$?
    [ $rc -eq 3 ] || fail "a regression and a failed write: exit $rc, expected 3"
    # Documented where compare is.
    "$canopy" compare --help >"$work/help"
    grep -q "1 a regression" "$work/help" && grep -q "2 bad input" "$work/help" && grep -q "3 an I/O failure" "$work/help" \
      || fail "compare --help does not list the exit codes" ;;
  interrupt_reference)
    # Issue 36: Ctrl-C during a reference's ray-trace ended canopy about 13 s later. Now within
    # a row of pixels: `canopy reference`, then a run's reference. Each trace takes far longer
    # than the test waits.
    stopped_within() {  # PID SECONDS: sends SIGINT, the process must exit within SECONDS; sets rc
      local start end
      start=$(date +%s%N)
      kill -INT "$1"
      wait "$1"; rc=$?
      end=$(date +%s%N)
      echo "exit $rc $(((end - start) / 1000000)) ms after SIGINT"
      [ $(((end - start) / 1000000)) -le $(($2 * 1000)) ] || fail "still running $2 s after SIGINT"
    }
    "$canopy" reference "$data/scenes/tiny.toml" --width 1024 --height 1024 --pixel-samples 1024 --no-cache \
      --out "$work/ref" >/dev/null 2>"$work/stderr" &
    pid=$!
    sleep 1.5
    kill -0 $pid 2>/dev/null || fail "the reference ended before SIGINT: $(cat "$work/stderr")"
    stopped_within $pid 2
    cat "$work/stderr"
    [ "$rc" -eq 130 ] || fail "reference: exit code $rc, expected 130"
    grep -q "canopy: stopping" "$work/stderr" || fail "SIGINT was not acknowledged"
    [ ! -e "$work/ref" ] || fail "an interrupted reference wrote images"
    sed -e "s|\.\./scenes/|$data/scenes/|" -e 's/resolutions = .*/resolutions = [[1024, 1024]]/' "$data/experiments/tiny.toml" >"$work/big.toml"
    printf '\n[reference]\npixel_samples = 1024\n' >>"$work/big.toml"
    "$canopy" run "$work/big.toml" --out "$work/out" --no-cache --no-progress >/dev/null 2>"$work/stderr" &
    pid=$!
    for _ in $(seq 300); do grep -q "writing to" "$work/stderr" || ! kill -0 $pid 2>/dev/null && break; sleep 0.1; done
    sleep 1.5
    kill -0 $pid 2>/dev/null || fail "the run ended before SIGINT: $(cat "$work/stderr")"
    stopped_within $pid 2
    cat "$work/stderr"
    [ "$rc" -eq 130 ] || fail "run: exit code $rc, expected 130"
    grep -q "canopy: stopping" "$work/stderr" || fail "SIGINT was not acknowledged in the run"
    [ "$(python3 -c "import json; print(json.load(open('$work/out/results.json'))['status'])")" = interrupted ] \
      || fail "the run is not recorded as interrupted" ;;
  *) fail "unknown case $case" ;;
esac
echo "ok: $case"
