#!/usr/bin/env bash
# scripts/reproduce runs each chosen paper experiment into its own folder, resumes a folder that
# holds a run, reads every claim's verdict from the new paper.md by the config's claim text, and
# compares it with the committed one. canopy is replaced by a stub that writes a paper.md in which
# every claim holds, and logs how it was called.
set -euo pipefail
script=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/canopy" <<'PY'
#!/usr/bin/env python3
import sys, tomllib
from pathlib import Path
args = sys.argv[1:]
config, out = args[1], Path(args[args.index("--out") + 1])
with open(sys.argv[0] + ".log", "a") as log:
    log.write(" ".join(args) + "\n")
claims = tomllib.load(open(config, "rb")).get("paper", {}).get("claim", [])
out.mkdir(parents=True, exist_ok=True)
(out / "results.json").write_text("{}")
(out / "paper.md").write_text("# stub\n\n## Claims\n\n" + "".join(f"- **holds** — {c['text']} (stub)\n" for c in claims))
(out / "paper.json").write_text('{"id": "stub", "title": "", "columns": [], "baseline": "", "column_key": "scene", "rows": [], "claims": []}')
PY
chmod +x "$work/canopy"
summary=$(python3 "$script" --only G-T7.1 L-T7.1 --out "$work/runs" --canopy "$work/canopy" --allow-dirty)
echo "$summary"
grep -q '^\[1/2\] G-T7.1 (elapsed 0:00:00, about ' <<<"$summary"
grep -q '^\[2/2\] L-T7.1 ' <<<"$summary"
[ "$(grep -c '^| G-T7.1 | ' <<<"$summary")" -eq 4 ]   # one row per claim of the config
[ "$(grep -c '^| L-T7.1 | ' <<<"$summary")" -eq 3 ]
grep -q '^| G-T7.1 | the power CDF removes light leaking better than VSM (ch. 7.4) | [a-z ]* | holds | ' <<<"$summary"
grep -q '^now: 7 holds; ' <<<"$summary"
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  grep -q '^plots: 2 folders' <<<"$summary"   # scripts/plot-paper ran over both runs' paper.json
fi
grep -q 'G-T7.1 --images png$' "$work/canopy.log"      # a new folder: no --resume
python3 "$script" --only G-T7.1 --out "$work/runs" --canopy "$work/canopy" --allow-dirty >/dev/null
tail -1 "$work/canopy.log" | grep -q -- '--images png --resume$'   # a folder holding a run: resumed
if python3 "$script" --quick --force --canopy "$work/canopy" --allow-dirty 2>/dev/null; then exit 1; fi
# A checkout with uncommitted changes outside results/ is refused (exit 2, naming the files) unless
# --allow-dirty; changes under results/ alone are not code. A copy of the script in a git repository
# of its own, with one paper experiment.
repo="$work/repo"
mkdir -p "$repo/scripts" "$repo/configs/experiments/paper" "$repo/results/paper"
cp "$script" "$repo/scripts/reproduce"; cp "$(dirname "$script")/plot-paper" "$repo/scripts/"
cp "$(dirname "$script")/../configs/experiments/paper/g-t7.1.toml" "$repo/configs/experiments/paper/"
echo committed >"$repo/results/paper/notes.md"
git -C "$repo" init -q && git -C "$repo" add -A && git -C "$repo" -c user.email=t@t -c user.name=t commit -qm init
python3 "$repo/scripts/reproduce" --out "$work/clean" --canopy "$work/canopy" >/dev/null   # clean: runs
echo changed >"$repo/results/paper/notes.md"
python3 "$repo/scripts/reproduce" --out "$work/results-only" --canopy "$work/canopy" >/dev/null  # results/ alone: runs
echo "# edited" >>"$repo/configs/experiments/paper/g-t7.1.toml"
rc=0; python3 "$repo/scripts/reproduce" --out "$work/dirty" --canopy "$work/canopy" >/dev/null 2>"$work/err" || rc=$?
[ $rc -eq 2 ] || { echo "a dirty checkout: exit $rc, expected 2"; exit 1; }
grep -q "uncommitted changes" "$work/err" && grep -q "configs/experiments/paper/g-t7.1.toml" "$work/err" \
  || { cat "$work/err"; echo "the refusal does not name the changed file"; exit 1; }
[ ! -e "$work/dirty" ] || { echo "a refused reproduction wrote $work/dirty"; exit 1; }
python3 "$repo/scripts/reproduce" --out "$work/dirty" --canopy "$work/canopy" --allow-dirty >/dev/null
echo "reproduce: ok"
