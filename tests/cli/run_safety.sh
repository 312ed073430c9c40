#!/usr/bin/env bash
# A run is never lost or clobbered, and says what it does: output-folder protection, resume after
# SIGKILL / SIGTERM / a full disk (through the test-only hooks CANOPY_TEST_KILL_AFTER_GROUPS and
# CANOPY_TEST_FAIL_WRITE_AFTER), progress, the compact table, `canopy list`, `--version`, the
# README's file list and committed paths. Usage: run_safety.sh CANOPY DATA_DIR CASE
set -uo pipefail
canopy=$1 data=$(cd "$2" && pwd) case=$3
checkout=$(cd "$data/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# The tiny experiment (3 cases), quick, sharing one reference cache; extra arguments follow.
run_tiny() {
  local out=$1; shift
  "$canopy" run "$data/experiments/tiny.toml" --out "$out" --quick --no-progress --reference-cache "$work/cache" "$@" \
    >"$work/stdout" 2>"$work/stderr"
}
# Two groups (tiny at two resolutions, 6 cases): a run is recorded, and resumed, group by group.
run_groups() {
  local out=$1; shift
  "$canopy" run "$work/groups.toml" --out "$out" --quick --no-progress --reference-cache "$work/cache" "$@" \
    >"$work/stdout" 2>"$work/stderr"
}
json() { python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print($2)" "$1"; }
snapshot() { (cd "$1" && find . -type f -exec sha256sum {} + | sort); }
no_temporary_files() { ! find "$1" -name '.*.tmp*' | grep -q . || fail "temporary files left in $1"; }
expect_refused() {  # regex of the message; the run's stdout/stderr are in $work
  local rc=$1 pattern=$2
  cat "$work/stderr"
  [ "$rc" -eq 2 ] || fail "exit code $rc, expected 2"
  grep -Eq "$pattern" "$work/stderr" || fail "message does not match '$pattern'"
}

# Same case ids, byte-identical images, identical errors: a resumed run is the uninterrupted one.
same_results() {
  local a=$1 b=$2
  python3 - "$a" "$b" <<'PY' || fail "$b differs from the uninterrupted run $a"
import json, sys
a, b = (json.load(open(d + "/results.json")) for d in sys.argv[1:3])
assert a["status"] == b["status"] == "complete", (a["status"], b["status"])
assert [c["id"] for c in a["cases"]] == [c["id"] for c in b["cases"]], "case ids"
for ca, cb in zip(a["cases"], b["cases"]):
    assert ca["image_error"] == cb["image_error"], ca["id"] + ": errors differ"
    assert ca["images"] == cb["images"], ca["id"] + ": image names differ"
    assert len(cb["timing"]["gpu_frame"]["samples_ms"]) == 3
PY
  diff <(cd "$a/images" && ls) <(cd "$b/images" && ls) || fail "different image files"
  for f in "$a"/images/*; do cmp -s "$f" "$b/images/$(basename "$f")" || fail "$(basename "$f") differs"; done
}

# An experiment other than tiny (another kernel sweep), with absolute scene paths.
sed -e 's/kernel = \[3, 5\]/kernel = [3, 7]/' -e "s|\.\./scenes/|$data/scenes/|" "$data/experiments/tiny.toml" >"$work/other.toml"
sed -e 's/^name = "tiny"/name = "tiny-groups"/' -e 's/resolutions = \[\[96, 64\]\]/resolutions = [[96, 64], [64, 48]]/' \
  -e "s|\.\./scenes/|$data/scenes/|" "$data/experiments/tiny.toml" >"$work/groups.toml"

# One group of 21 cases (the hard shadow, then PCF at 5 kernels x 4 map sizes): two chunks (16 cases
# each at most, the baseline in both).
sed -e 's/^name = "tiny"/name = "tiny-chunks"/' -e 's/resolutions = \[\[96, 64\]\]/resolutions = [[48, 32]]/' \
  -e 's/^resolution = 256$/resolution = [64, 128, 256, 512]/' -e 's/kernel = \[3, 5\]/kernel = [3, 5, 7, 9, 11]/' \
  -e "s|\.\./scenes/|$data/scenes/|" "$data/experiments/tiny.toml" >"$work/chunks.toml"
# The hard shadow has one map size: the baseline stays one case.
python3 - "$work/chunks.toml" <<'PY'
import sys
path = sys.argv[1]
text = open(path).read().replace('name = "shadow.hard"\n[technique.params]\nresolution = [64, 128, 256, 512]',
                                 'name = "shadow.hard"\n[technique.params]\nresolution = 256', 1)
open(path, "w").write(text)
PY
run_chunks() {
  local out=$1; shift
  "$canopy" run "$work/chunks.toml" --out "$out" --quick --no-progress --no-reference "$@" >"$work/stdout" 2>"$work/stderr"
}

case $case in
  folder_protection)
    run_tiny "$work/a" || fail "first run failed: $(cat "$work/stderr")"
    before=$(snapshot "$work/a")
    "$canopy" run "$work/other.toml" --out "$work/a" --quick --no-progress --reference-cache "$work/cache" >"$work/stdout" 2>"$work/stderr"
    expect_refused $? "holds another run .*experiment 'tiny'.*"
    grep -q "config_hash: the folder's run has" "$work/stderr" || fail "does not say the config differs"
    grep -q -- "--force" "$work/stderr" || fail "does not say how to replace it"
    run_tiny "$work/a" --images png; expect_refused $? "images: the folder's run has 'all', this one 'png'"
    "$canopy" run "$data/experiments/tiny.toml" --out "$work/a" --no-progress --reference-cache "$work/cache" >"$work/stdout" 2>"$work/stderr"
    expect_refused $? "quick: the folder's run has 'true', this one 'false'"
    run_tiny "$work/a" --no-reference; expect_refused $? "reference: the folder's run has 'on', this one 'off'"
    [ "$(snapshot "$work/a")" == "$before" ] || fail "a refused run changed the folder"

    # Committed results: refused even when empty or new.
    mkdir -p "$work/checkout/results/paper/G-X"
    run_tiny "$work/checkout/results/paper/G-X"; expect_refused $? "committed results"
    [ -z "$(ls -A "$work/checkout/results/paper/G-X")" ] || fail "wrote into results/paper"
    run_tiny "$work/checkout/results/baselines/new"; expect_refused $? "committed results"
    [ ! -e "$work/checkout/results/baselines/new" ] || fail "created a folder under results/baselines"

    # Someone else's files; nothing to resume; a file.
    mkdir -p "$work/mine" && echo notes >"$work/mine/notes.txt"
    run_tiny "$work/mine"; expect_refused $? "holds no canopy run"
    [ "$(ls -A "$work/mine")" == "notes.txt" ] || fail "wrote into a foreign folder"
    run_tiny "$work/new" --resume; expect_refused $? "nothing to resume"
    [ ! -e "$work/new" ] || fail "--resume created a folder"
    run_tiny "$work/mine/notes.txt"; expect_refused $? "names a file"

    # The same run again continues it: every case is kept, nothing is measured again.
    samples=$(json "$work/a/results.json" "[c['timing']['gpu_frame']['samples_ms'] for c in j['cases']]")
    run_tiny "$work/a" || fail "the same run was refused: $(cat "$work/stderr")"
    grep -q "resuming the run" "$work/stderr" || fail "does not say it resumes"
    [ "$(json "$work/a/results.json" "[c['timing']['gpu_frame']['samples_ms'] for c in j['cases']]")" == "$samples" ] \
      || fail "finished cases were measured again" ;;

  force_replaces)
    run_tiny "$work/a" || fail "first run failed"
    echo notes >"$work/a/notes.txt"
    "$canopy" run "$work/other.toml" --out "$work/a" --quick --no-progress --reference-cache "$work/cache" --force \
      >"$work/stdout" 2>"$work/stderr" || fail "--force run failed: $(cat "$work/stderr")"
    cat "$work/stderr"
    ! ls "$work/a/images" | grep -q "kernel-5" || fail "the replaced run's images stayed"
    ls "$work/a/images" | grep -q "kernel-7" || fail "the new run wrote no images"
    [ "$(json "$work/a/results.json" "len(j['cases'])")" == 3 ] || fail "results.json is not the new run's"
    [ -f "$work/a/notes.txt" ] || fail "--force removed a file canopy did not write"
    # A user's own files named like canopy's, in a folder holding no canopy run: refused even
    # with --force, and every file stays.
    mkdir -p "$work/user/images"
    for f in results.csv paper.md images/holiday.png; do echo "mine $f" >"$work/user/$f"; done
    before=$(snapshot "$work/user")
    run_tiny "$work/user" --force; expect_refused $? "holds no canopy run.*with or without --force"
    [ "$(snapshot "$work/user")" == "$before" ] || fail "--force changed a folder holding no canopy run"
    # Beside a canopy run, --force removes what that run recorded and keeps the user's image.
    run_tiny "$work/b" || fail "run into b failed"
    echo holiday >"$work/b/images/holiday.png"
    "$canopy" run "$work/other.toml" --out "$work/b" --quick --no-progress --reference-cache "$work/cache" --force \
      >"$work/stdout" 2>"$work/stderr" || fail "--force run into b failed: $(cat "$work/stderr")"
    [ "$(cat "$work/b/images/holiday.png")" == holiday ] || fail "--force removed a user's image beside a run"
    mkdir -p "$work/checkout/results/paper/G-X"
    run_tiny "$work/checkout/results/paper/G-X" --force || fail "--force into results/paper failed"
    [ -s "$work/checkout/results/paper/G-X/results.json" ] || fail "nothing written with --force" ;;

  interrupted_chunks)
    # A group stopped between its chunks keeps the finished chunk's cases (with the baseline they
    # were paired with) and leaves no image without its record; --resume measures the rest only.
    for signal in INT KILL; do
      CANOPY_TEST_KILL_AFTER_CHUNKS=1 CANOPY_TEST_KILL_SIGNAL=$signal run_chunks "$work/$signal"; rc=$?
      cat "$work/stderr"
      [ $rc -ne 0 ] || fail "$signal: the run was not stopped"
      python3 - "$work/$signal" <<'PY' || fail "$signal: the finished chunk was not recorded alone"
import json, os, sys
folder = sys.argv[1]
j = json.load(open(folder + "/results.json"))
assert j["planned_cases"] == 21, j["planned_cases"]
assert len(j["cases"]) == 16, ("recorded cases", len(j["cases"]))
assert len(j["groups"][0]["chunks"]) == 1, j["groups"][0]["chunks"]
assert j["groups"][0]["chunks"][0]["cases"] == [c["id"] for c in j["cases"]], "the chunk's cases"
recorded = {os.path.basename(v) for c in j["cases"] for v in c["images"].values() if v}
on_disk = {f for f in os.listdir(folder + "/images") if not f.startswith(".")}
assert on_disk <= recorded, ("images without a record", sorted(on_disk - recorded)[:5])
PY
      kept=$(json "$work/$signal/results.json" "[c['timing']['gpu_frame']['samples_ms'] for c in j['cases']]")
      run_chunks "$work/$signal" --resume || fail "$signal: resume failed: $(cat "$work/stderr")"
      cat "$work/stderr"
      [ "$(json "$work/$signal/results.json" "j['status'], len(j['cases']), len(j['groups'][0]['chunks'])")" == "complete 21 2" ] \
        || fail "$signal: the resumed run is not complete with 21 cases in 2 chunks"
      [ "$(json "$work/$signal/results.json" "[c['timing']['gpu_frame']['samples_ms'] for c in j['cases'][:16]]")" == "$kept" ] \
        || fail "$signal: the finished chunk was measured again"
      # The second chunk paired its cases with the baseline measured again beside them.
      [ "$(json "$work/$signal/results.json" "j['groups'][0]['chunks'][1]['cases'][0] == j['groups'][0]['baseline'], len(j['groups'][0]['chunks'][1]['cases'])")" == "True 6" ] \
        || fail "$signal: the second chunk lacks the baseline or its 5 cases"
      no_temporary_files "$work/$signal"
    done ;;

  degenerate_scene)
    # A camera inside a closed sphere: the reference is one colour and no pixel is lit, so every
    # technique would score "perfect". The case is flagged on stderr, in results.json, results.csv
    # and results.md's table.
    cat >"$work/inside.toml" <<'TOML'
[scene]
name = "inside"
[camera]
position = [0, 0, 0]
target = [0, 0, -1]
[[light]]
type = "directional"
direction = [0, -1, 0]
[[object]]
shape = "sphere"
radius = 5
TOML
    sed -e 's/^name = "tiny"/name = "tiny-inside"/' -e "s|\.\./scenes/tiny.toml|$work/inside.toml|" \
      "$data/experiments/tiny.toml" >"$work/inside-experiment.toml"
    "$canopy" run "$work/inside-experiment.toml" --out "$work/a" --quick --no-progress --reference-cache "$work/cache" \
      >"$work/stdout" 2>"$work/stderr" || fail "run failed: $(cat "$work/stderr")"
    cat "$work/stderr"
    grep -q "reference of inside 96x64 is degenerate (uniform image, no lit pixels)" "$work/stderr" \
      || fail "no warning on stderr"
    [ "$(json "$work/a/results.json" "j['references'][0]['degenerate']")" == "['uniform image', 'no lit pixels']" ] \
      || fail "results.json does not record why the reference is degenerate"
    grep -q '"degenerate reference: uniform image, no lit pixels"' "$work/a/results.csv" || fail "results.csv lacks the flag"
    [ "$(grep -c '\*\*degenerate reference: uniform image, no lit pixels\*\*' "$work/a/results.md")" -eq 3 ] \
      || fail "results.md's table does not flag each of the 3 cases"
    # The ordinary tiny scene is not flagged.
    run_tiny "$work/b" || fail "tiny run failed"
    [ "$(json "$work/b/results.json" "j['references'][0]['degenerate']")" == "[]" ] || fail "the tiny scene is flagged"
    ! grep -q "degenerate" "$work/b/results.md" || fail "results.md flags the tiny scene" ;;

  moved_build)
    # A run from another checkout: the config's checkout gives the commit, the changed files and
    # the recorded paths; the binary's own commit is recorded apart and the mismatch flagged.
    repo="$work/elsewhere"
    mkdir -p "$repo/configs"
    cp -r "$data/experiments" "$data/scenes" "$repo/configs/"
    git -C "$repo" init -q && git -C "$repo" add -A
    git -C "$repo" -c user.email=t@t -c user.name=t commit -qm "another checkout"
    head=$(git -C "$repo" rev-parse HEAD)
    binary=$("$canopy" --version | sed -n 's/.*commit \([0-9a-f]*\).*/\1/p')
    echo "# a local edit" >>"$repo/configs/scenes/tiny.toml"
    (cd "$work" && "$canopy" run "$repo/configs/experiments/tiny.toml" --out "$work/a" --quick --no-progress \
      --reference-cache "$work/cache" >"$work/stdout" 2>"$work/stderr") || fail "run failed: $(cat "$work/stderr")"
    cat "$work/stderr"
    python3 - "$work/a/results.json" "$head" "$binary" <<'PY' || fail "results.json misattributes the run"
import json, sys
j = json.load(open(sys.argv[1])); e = j["environment"]
head, binary = sys.argv[2], sys.argv[3]
assert e["commit"] == head, ("commit", e["commit"], head)
assert e["commit_dirty"] and e["commit_dirty_files"] == ["configs/scenes/tiny.toml"], e["commit_dirty_files"]
assert binary and e["binary_commit"] == binary, ("binary_commit", e["binary_commit"], binary)
assert e["commit_mismatch"] is True
assert j["config"] == "configs/experiments/tiny.toml", j["config"]
assert [f["file"] for f in j["inputs"]] == ["configs/experiments/tiny.toml", "configs/scenes/tiny.toml"], j["inputs"]
PY
    grep -q "this binary was built from commit ${binary:0:12} but the run is in $repo" "$work/stderr" \
      || fail "no warning that the binary's commit is not the checkout's"
    grep -q "the binary was built from $binary, not from the checkout's commit $head" "$work/a/results.md" \
      || fail "results.md does not flag the mismatch"
    cmp -s "$work/a/experiment.toml" "$repo/configs/experiments/tiny.toml" || fail "experiment.toml is not the config run"
    [ ! -e "$repo/.git/index.lock" ] || fail "git's lock left in the checkout"
    # In its own checkout, nothing is flagged.
    run_tiny "$work/b" || fail "run in the build's checkout failed"
    [ "$(json "$work/b/results.json" "j['environment']['commit_mismatch']")" == False ] \
      || fail "a run in the binary's own checkout is flagged" ;;

  resume_after_kill)
    run_groups "$work/whole" || fail "uninterrupted run failed"
    CANOPY_TEST_KILL_AFTER_GROUPS=1 run_groups "$work/killed"; rc=$?
    [ $rc -eq 137 ] || fail "exit code $rc after SIGKILL, expected 137"
    [ "$(json "$work/killed/results.json" "j['status'], len(j['cases'])")" == "running 3" ] \
      || fail "the killed run did not record its first group's 3 cases"
    kept=$(json "$work/killed/results.json" "j['cases'][0]['timing'], j['groups'][0]['chunks']")
    run_groups "$work/killed" --resume || fail "resume failed: $(cat "$work/stderr")"
    cat "$work/stderr"
    [ "$(json "$work/killed/results.json" "j['cases'][0]['timing'], j['groups'][0]['chunks']")" == "$kept" ] \
      || fail "a finished group was redone"
    [ "$(json "$work/killed/results.json" "len(j['resumed_at'])")" == 1 ] || fail "resumed_at not recorded"
    same_results "$work/whole" "$work/killed"
    no_temporary_files "$work/killed" ;;

  resume_mid_group)
    run_groups "$work/whole" || fail "uninterrupted run failed"
    # Killed after the second group's first case has its images written, before results.json records that group.
    CANOPY_TEST_KILL_AFTER_GROUPS=1 CANOPY_TEST_KILL_MID_GROUP=1 run_groups "$work/half"; rc=$?
    [ $rc -eq 137 ] || fail "exit code $rc, expected 137"
    [ "$(json "$work/half/results.json" "len(j['cases'])")" == 3 ] || fail "expected the first group's 3 cases recorded"
    ls "$work/half/images" | grep -q "tiny_64x48_shadow.hard_resolution-256.png" \
      || fail "the half-written group left no images (test premise)"
    touch -d '2000-01-01' "$work/half/images/"tiny_64x48*
    touch "$work/half/images/.tiny_96x64_shadow.tmp999.png"  # as a write cut short would leave
    # A recorded group one of whose cases lost a file is run again, every case of it.
    rm "$work/half/images/"tiny_96x64*shadow.hard*.error.png
    lost=$(json "$work/half/results.json" "j['cases'][1]['timing']['gpu_frame']['samples_ms']")
    run_groups "$work/half" || fail "resume failed: $(cat "$work/stderr")"
    [ "$(json "$work/half/results.json" "j['cases'][1]['timing']['gpu_frame']['samples_ms']")" != "$lost" ] \
      || fail "a group whose baseline's error map was gone was kept"
    [ -n "$(find "$work/half/images" -name 'tiny_64x48*hard*.png' -newermt '2001-01-01')" ] \
      || fail "the half-written group was not redone"
    same_results "$work/whole" "$work/half"
    no_temporary_files "$work/half" ;;

  resume_after_term)
    run_groups "$work/whole" || fail "uninterrupted run failed"
    for signal in TERM INT; do
      CANOPY_TEST_KILL_SIGNAL=$signal CANOPY_TEST_KILL_AFTER_GROUPS=1 run_groups "$work/$signal"; rc=$?
      cat "$work/stderr"
      expected=$([ $signal == TERM ] && echo 143 || echo 130)
      [ $rc -eq "$expected" ] || fail "exit code $rc after SIG$signal, expected $expected"
      [ "$(json "$work/$signal/results.json" "j['status'], len(j['cases'])")" == "interrupted 3" ] \
        || fail "SIG$signal did not leave an interrupted record of the finished group"
      grep -q "interrupted after 3 of 6 cases" "$work/stderr" || fail "no message"
      run_groups "$work/$signal" || fail "resume failed: $(cat "$work/stderr")"
      same_results "$work/whole" "$work/$signal"
    done
    # A real SIGTERM from outside, in the middle of a long case.
    sed 's/repetitions = 3/repetitions = 100000/' "$work/other.toml" >"$work/long.toml"
    "$canopy" run "$work/long.toml" --out "$work/long" --no-progress --reference-cache "$work/cache" >/dev/null 2>"$work/stderr" &
    pid=$!
    for _ in $(seq 100); do [ -s "$work/long/results.json" ] && break; sleep 0.1; done
    sleep 1
    kill -TERM $pid
    wait $pid; rc=$?
    [ $rc -eq 143 ] || fail "exit code $rc after kill -TERM, expected 143: $(cat "$work/stderr")"
    [ "$(json "$work/long/results.json" "j['status']")" == interrupted ] || fail "not recorded as interrupted"
    no_temporary_files "$work/long" ;;

  concurrent_run)
    # Two canopy processes never write into one folder: the second is refused while the first runs.
    sed 's/repetitions = 3/repetitions = 100000/' "$work/other.toml" >"$work/long.toml"
    args=(run "$work/long.toml" --out "$work/a" --no-progress --reference-cache "$work/cache")
    "$canopy" "${args[@]}" >/dev/null 2>"$work/first" &
    pid=$!
    for _ in $(seq 100); do [ -s "$work/a/results.json" ] && break; sleep 0.1; done
    "$canopy" "${args[@]}" >"$work/stdout" 2>"$work/stderr"; rc=$?
    kill -INT $pid
    wait $pid
    expect_refused $rc "another canopy run is writing to this folder"
    [ "$(json "$work/a/results.json" "j['status']")" == interrupted ] || fail "the first run's record was disturbed" ;;

  disk_full)
    run_groups "$work/whole" || fail "uninterrupted run failed"
    # Writes: 4 reports (no pareto.md yet: no case) and the config's copy, then per group 4
    # reference images, 5 images per case (3 cases), results.json for its one chunk, 5 reports
    # (pareto.md too): 30 up to the first group's record; the 35th (the second group's first EXR,
    # after its 4 reference images) fails.
    CANOPY_TEST_FAIL_WRITE_AFTER=34 run_groups "$work/full"; rc=$?
    cat "$work/stderr"
    [ $rc -eq 1 ] || fail "exit code $rc, expected 1"
    grep -Eq "cannot write .*tiny_64x48_shadow\.hard_resolution-256\.exr: No space left on device" "$work/stderr" \
      || fail "no reason on stderr"
    [ "$(json "$work/full/results.json" "j['status'], len(j['cases'])")" == "failed 3" ] || fail "results.json is not 'failed'"
    json "$work/full/results.json" "j['error']" | grep -q "No space left on device" || fail "the reason is not recorded"
    no_temporary_files "$work/full"
    # Space again: the same command continues it.
    run_groups "$work/full" || fail "resume after a full disk failed: $(cat "$work/stderr")"
    same_results "$work/whole" "$work/full"
    # The very first write failing is reported the same way.
    CANOPY_TEST_FAIL_WRITE_AFTER=0 run_tiny "$work/first"; rc=$?
    [ $rc -eq 1 ] && grep -q "results.json: No space left on device" "$work/stderr" || fail "first write: rc $rc, $(cat "$work/stderr")" ;;

  disk_stays_full)
    # Every write from case 1's fifth image on fails (4 reports, the config's copy, 4 reference
    # images, 4 of case 1's images before it): not even the failure can be recorded.
    CANOPY_TEST_FAIL_WRITE_AFTER=13+ run_tiny "$work/full"; rc=$?
    cat "$work/stderr"
    [ $rc -eq 1 ] || fail "exit code $rc, expected 1"
    grep -q "No space left on device" "$work/stderr" || fail "no reason on stderr"
    grep -q "could not record this either" "$work/stderr" || fail "does not say the record is stale"
    no_temporary_files "$work/full"
    run_tiny "$work/full" || fail "resume failed: $(cat "$work/stderr")"
    [ "$(json "$work/full/results.json" "j['status'], len(j['cases'])")" == "complete 3" ] || fail "not completed" ;;

  progress)
    "$canopy" run "$data/experiments/tiny.toml" --out "$work/a" --quick --reference-cache "$work/cache" >/dev/null 2>"$work/first" \
      || fail "run failed"
    "$canopy" run "$data/experiments/tiny.toml" --out "$work/b" --quick --reference-cache "$work/cache" >/dev/null 2>"$work/second" \
      || fail "run failed"
    cat "$work/first" "$work/second"
    grep -q "ray-tracing reference tiny 96x64" "$work/first" || fail "first run does not say it ray-traces"
    grep -Eq "reference tiny 96x64 ray-traced in [0-9.]+ s" "$work/first" || fail "never says the reference finished"
    grep -Eq "done in [0-9.]+ s, ETA [0-9]+:[0-9]{2}" "$work/first" || fail "no ETA"
    grep -q "finished 3 of 3 cases in" "$work/first" || fail "never says the run finished"
    grep -q "reference tiny 96x64: from the cache" "$work/second" || fail "second run does not say 'from the cache'"
    ! grep -q "ray-tracing" "$work/second" || fail "second run claims to ray-trace a cached reference" ;;

  console_table)
    run_tiny "$work/a" || fail "run failed"
    cat "$work/stdout"
    awk 'length($0) > 120 { exit 1 }' "$work/stdout" || fail "stdout has lines over 120 characters"
    grep -Eq "\| shadow.pcf +\| resolution=256 kernel=3 " "$work/stdout" || fail "the default value of a swept parameter is not shown"
    grep -Eq "\| shadow.pcf +\| resolution=256 kernel=5 " "$work/stdout" || fail "kernel=5 row missing"
    grep -q "penumbra RMSE" "$work/stdout" || fail "no key error columns"
    ! grep -q "passes (GPU ms)" "$work/stdout" || fail "stdout has the full table"
    grep -q "passes (GPU ms)" "$work/a/results.md" || fail "results.md lost the full table"
    grep -q "resolution=256 kernel=3" "$work/a/results.md" || fail "results.md lacks kernel=3" ;;

  list_and_version)
    "$canopy" --version >"$work/version" || fail "--version failed"
    cat "$work/version"
    grep -Eq "^canopy [0-9]+\.[0-9]+\.[0-9]+ \(([A-Za-z]+ )?build, commit ([0-9a-f]{40}|unknown)\)$" \
      "$work/version" || fail "--version prints no version"
    "$canopy" run --help >"$work/help" || fail "run --help failed"
    grep -q -- "--resume" "$work/help" && grep -q -- "--force" "$work/help" || fail "run --help lacks --resume or --force"
    "$canopy" list >"$work/list" || fail "list failed"
    for technique in shadow.pcss shadow.ssss; do
      grep -A3 "^$technique\$" "$work/list" | grep -q "requires: an area light (rect or sphere)" \
        || fail "$technique does not say it needs an area light"
    done
    grep -A3 "^shadow.hard\$" "$work/list" | grep -q "requires: a shadow-casting light" || fail "shadow.hard says no requirement"
    grep -A3 "^grass.geometry\$" "$work/list" | grep -q "requires: renders 'grass' populations" || fail "grass.geometry hides its population"
    grep -A12 '^population kind "grass"' "$work/list" | grep -q "^    cells_x " || fail "list lacks the grass population kind's parameters"
    # Defaults and ranges as declared (issue 36: 0.15f was shown as 0.15000000596046448).
    ! grep -E '[0-9]\.[0-9]*(0000|9999)[0-9]+' "$work/list" || fail "list shows a float's double noise"
    # Parameter rows: the type and the default start in the same column whatever the name's length.
    [ "$(grep -E '^    [a-z_]+ ' "$work/list" | awk '{ print index($0, " default ") }' | sort -u | wc -l)" -eq 1 ] \
      || fail "the default column drifts"
    [ "$(grep -E '^    [a-z_]+ ' "$work/list" | awk '{ match($0, /(int|float|bool|one of|file path)/); print RSTART }' | sort -u | wc -l)" -eq 1 ] \
      || fail "the type column drifts" ;;

  readme_files)
    # Every kind of file `canopy run` and `canopy reference` write is in the README's tables: its
    # name, or its suffix after the case id or reference stem, in backquotes.
    run_tiny "$work/a" || fail "run failed"
    "$canopy" reference "$data/scenes/tiny.toml" --width 32 --height 16 --light-samples 1 --pixel-samples 1 \
      --reference-cache "$work/cache" --out "$work/ref" >/dev/null || fail "reference failed"
    python3 - "$work/a" "$work/ref" "$checkout/README.md" <<'PY' || fail "the README does not list every file"
import json, os, sys
run, ref, readme = sys.argv[1], sys.argv[2], open(sys.argv[3]).read()
stems = [c["id"] for c in json.load(open(run + "/results.json"))["cases"]] + ["reference_tiny_96x64", "tiny_32x16"]
files = [os.path.relpath(os.path.join(d, f), run) for d, _, fs in os.walk(run) for f in fs] + os.listdir(ref)
missing = []
for f in files:
    name = os.path.basename(f)
    stem = max((s for s in stems if name.startswith(s + ".")), key=len, default=None)
    kind = name if stem is None else name[len(stem):]
    if kind + "`" not in readme:
        missing.append(f"{f} ({kind})")
print("\n".join(missing))
sys.exit(1 if missing else 0)
PY
    ;;

  committed_paths)
    # Committed results name files relative to the checkout, never where it was on some machine.
    ! grep -rIE '(`|")/(home|work|root|tmp|Users|builds?)/' "$checkout/results" | grep -v '^.*/cache/' \
      || fail "committed results name absolute paths"
    run_tiny "$work/a" || fail "run failed"
    [ "$(json "$work/a/results.json" "j['config']")" == tests/data/experiments/tiny.toml ] \
      || fail "results.json records $(json "$work/a/results.json" "j['config']")" ;;

  *) fail "unknown case $case" ;;
esac
echo "ok: $case"
