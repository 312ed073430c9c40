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
    "$canopy" --help | grep -q "run" || fail "--help lists no run command"
    "$canopy" run --help | grep -q -- "--quick" || fail "run --help lists no --quick"
    "$canopy" list | grep -q "shadow.pcf" || fail "list lacks shadow.pcf"
    "$canopy" list | grep -q "kernel" || fail "list lacks the kernel parameter"
    "$canopy" devices | grep -q "0:" || fail "devices lists no device" ;;
  run)
    "$canopy" run "$data/experiments/tiny.toml" --out "$work/out" --quick >"$work/stdout" 2>"$work/stderr" || fail "run failed: $(cat "$work/stderr")"
    cat "$work/stdout"
    for f in results.json results.csv results.md; do [ -s "$work/out/$f" ] || fail "missing $f"; done
    [ "$(ls "$work/out/images" | grep -c '\.png$')" -eq 3 ] || fail "expected 3 PNGs"
    [ "$(ls "$work/out/images" | grep -c '\.exr$')" -eq 3 ] || fail "expected 3 EXRs"
    grep -q "shadow.hard" "$work/stdout" || fail "table lacks shadow.hard" ;;
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
  *) fail "unknown case $case" ;;
esac
echo "ok: $case"
