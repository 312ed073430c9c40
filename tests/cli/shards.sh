#!/usr/bin/env bash
# canopy plan, run --shard i/N and merge (issue 12): the tiny scene at three resolutions (3 groups,
# 9 cases) split into 2 shards. Every group lies whole in one shard; the merge of the shards has
# the cases of a single run in its order with the same error values and timing statistics; merging
# again rewrites the same folder; a missing shard, a shard given twice, another config's shard and
# a whole run are named and refused.
# Usage: shards.sh CANOPY DATA_DIR
set -uo pipefail
canopy=$1
data=$2
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
json() { python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print($2)" "$1"; }
sed -e 's/^name = "tiny"/name = "tiny-shards"/' -e 's/resolutions = \[\[96, 64\]\]/resolutions = [[96, 64], [64, 48], [48, 32]]/' \
  -e "s|\.\./scenes/|$data/scenes/|" "$data/experiments/tiny.toml" >"$work/three.toml"
sed -e 's/kernel = \[3, 5\]/kernel = [3, 7]/' "$work/three.toml" >"$work/other.toml"
run() { "$canopy" run "$@" --quick --no-progress --reference-cache "$work/cache" >"$work/stdout" 2>"$work/stderr"; }

# The plan: keys depend on the case alone, each group is in one shard, both shards have work.
"$canopy" plan "$work/three.toml" --shards 2 >"$work/plan" || fail "plan failed"
cat "$work/plan"
[ "$(grep -c '^| [0-9a-f]\{16\} | tiny_' "$work/plan")" -eq 9 ] || fail "plan does not list 9 cases with 16-digit keys"
key() { grep " | $2 " "$1" | awk -F'|' '{gsub(/ /, "", $2); print $2}'; }
"$canopy" plan "$data/experiments/tiny.toml" >"$work/plan-tiny" || fail "plan of tiny failed"
[ "$(key "$work/plan" tiny_96x64_shadow.hard_resolution-256)" = "$(key "$work/plan-tiny" tiny_96x64_shadow.hard_resolution-256)" ] \
  || fail "a case's key changed with the experiment around it"
for res in 96x64 64x48 48x32; do
  [ "$(grep " | tiny $res " "$work/plan" | awk -F'|' '{print $7}' | sort -u | wc -l)" -eq 1 ] || fail "group $res split across shards"
done
grep -q -- "--shard 1/2: [1-9]" "$work/plan" && grep -q -- "--shard 2/2: [1-9]" "$work/plan" || fail "a shard without cases"

# Whole run and the two shards, sharing the reference cache.
run "$work/three.toml" --out "$work/whole" || fail "whole run failed: $(cat "$work/stderr")"
run "$work/three.toml" --out "$work/s1" --shard 1/2 || fail "shard 1/2 failed: $(cat "$work/stderr")"
run "$work/three.toml" --out "$work/s2" --shard 2/2 || fail "shard 2/2 failed: $(cat "$work/stderr")"
[ "$(json "$work/s1/results.json" "j['shard']")" = "1/2" ] || fail "results.json does not name its shard"
n1=$(json "$work/s1/results.json" "len(j['cases'])"); n2=$(json "$work/s2/results.json" "len(j['cases'])")
[ $((n1 + n2)) -eq 9 ] || fail "the shards hold $n1 + $n2 cases, not 9"
# A shard's folder is that shard's: another shard into it is refused.
run "$work/three.toml" --out "$work/s1" --shard 2/2; [ $? -eq 2 ] && grep -q "shard" "$work/stderr" || fail "shard 2/2 went into shard 1/2's folder"

"$canopy" merge "$work/s2" "$work/s1" --out "$work/merged" >"$work/stdout" 2>"$work/stderr" || fail "merge failed: $(cat "$work/stderr")"
cat "$work/stdout"
python3 - "$work/whole/results.json" "$work/merged/results.json" <<'PY' || fail "the merge differs from a single run"
import json, sys
whole, merged = (json.load(open(p)) for p in sys.argv[1:])
ids = [c["id"] for c in whole["cases"]]
assert [c["id"] for c in merged["cases"]] == ids, ("case order", [c["id"] for c in merged["cases"]], ids)
assert [g["name"] for g in merged["groups"]] == [g["name"] for g in whole["groups"]], "group order"
for a, b in zip(whole["cases"], merged["cases"]):
    assert a["image_error"] == b["image_error"], (a["id"], "error values differ")
    assert b["timing"]["gpu_frame"]["stats_ms"]["count"] == a["timing"]["gpu_frame"]["stats_ms"]["count"] > 0, a["id"]
    assert b["params"] == a["params"], a["id"]
    assert a["node"] == "" and b["node"] != "", (a["id"], "the node that measured a merged case")
    g = merged["groups"][b["group"]]
    assert b["id"] in g["cases"], (b["id"], "not in its group")
ref = lambda r: (r["scene"], r["width"], r["height"], r["key"])
assert [ref(r) for r in merged["references"]] == [ref(r) for r in whole["references"]], "references"
assert merged["status"] == "complete", merged["status"]
assert [m["shard"] for m in merged["merged_from"]] == ["1/2", "2/2"], merged["merged_from"]
assert merged["planned_cases"] == 9 and merged["shard"] == ""
print("merged == whole: 9 cases, same ids, order, errors and parameters")
PY
for f in results.csv results.md results.gbench.json pareto.md; do [ -s "$work/merged/$f" ] || fail "merge wrote no $f"; done
for f in $(json "$work/merged/results.json" "' '.join(c['images']['png'] for c in j['cases'])"); do
  [ -s "$work/merged/$f" ] || fail "merged folder lacks $f"
done
# Again: the same folder, byte for byte.
(cd "$work/merged" && find . -type f -exec sha256sum {} + | sort) >"$work/first"
"$canopy" merge "$work/s1" "$work/s2" --out "$work/merged" >/dev/null 2>&1 || fail "second merge failed"
(cd "$work/merged" && find . -type f -exec sha256sum {} + | sort) | diff - "$work/first" || fail "merging again changed the folder"

# Refusals and a missing shard.
"$canopy" merge "$work/s1" --out "$work/part" >"$work/stdout" 2>"$work/stderr"; rc=$?
[ $rc -eq 1 ] || fail "a missing shard: exit $rc, expected 1"
grep -q "cases are in no shard given" "$work/stderr" && grep -q "$(json "$work/s2/results.json" "j['cases'][0]['id']")" "$work/stderr" \
  || fail "the missing cases are not listed: $(cat "$work/stderr")"
"$canopy" merge "$work/s1" "$work/s1" --out "$work/twice" 2>"$work/stderr"; [ $? -eq 2 ] && grep -q "given twice" "$work/stderr" \
  || fail "a shard given twice: $(cat "$work/stderr")"
# An input is never the output: merging into a shard's folder is refused, with --force too, and
# leaves the shard as it was (a second merge still works).
(cd "$work/s1" && find . -type f -exec sha256sum {} + | sort) >"$work/s1.before"
for force in "" --force; do
  "$canopy" merge "$work/s1" "$work/s2" --out "$work/s1/" $force 2>"$work/stderr"; [ $? -eq 2 ] \
    && grep -q "one of the shards being merged" "$work/stderr" || fail "merge into a shard ($force): $(cat "$work/stderr")"
done
(cd "$work/s1" && find . -type f -exec sha256sum {} + | sort) | diff - "$work/s1.before" || fail "a refused merge changed shard s1"
run "$work/other.toml" --out "$work/o1" --shard 1/2 || fail "other config's shard failed"
"$canopy" merge "$work/s1" "$work/o1" --out "$work/mixed" 2>"$work/stderr"; [ $? -eq 2 ] && grep -q "config hash" "$work/stderr" \
  || fail "another config's shard: $(cat "$work/stderr")"
"$canopy" merge "$work/whole" --out "$work/notshard" 2>"$work/stderr"; [ $? -eq 2 ] && grep -q "not a shard" "$work/stderr" \
  || fail "a whole run: $(cat "$work/stderr")"
run "$work/three.toml" --out "$work/bad" --shard 3/2; [ $? -eq 2 ] && grep -q "1 to N" "$work/stderr" || fail "--shard 3/2: $(cat "$work/stderr")"
run "$work/three.toml" --out "$work/bad" --shard 4/4; [ $? -eq 2 ] && grep -q "has no group" "$work/stderr" || fail "an empty shard: $(cat "$work/stderr")"
[ ! -e "$work/bad/results.json" ] || fail "a refused shard wrote results"
echo "shards: ok"
