#!/usr/bin/env bash
# The football field (Lemme's 380 x 532 cells) renders through grass.lod's quadtree in its quick
# mode (configs/experiments/grass/football-quick.toml): every view finishes, with no NaN, and the
# quadtree's counts say what each band drew: no blades from high above, blades near and macro-cells
# in the middle and far bands at a player's height and from inside the grass, and far fewer far
# draws than far cells. Usage: football_quick.sh CANOPY SOURCE_DIR
set -uo pipefail
canopy=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

cd "$source_dir" || fail "no source folder $source_dir"
SECONDS=0
"$canopy" run configs/experiments/grass/football-quick.toml --out "$work/run" --quick --no-reference --images none \
  >"$work/log" 2>&1 || { cat "$work/log"; fail "canopy run failed"; }
echo "ran in ${SECONDS} s"
csv="$work/run/results.csv"
[ -f "$csv" ] || fail "no results.csv"
# The value of column NAME on the row of scene SCENE.
value() {
  awk -F, -v scene="$1" -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i; next }
                                     { s = $2; gsub(/"/, "", s) } s == scene { print $c }' "$csv"
}
for scene in high-quick player-quick ant-quick; do
  [ "$(value "$scene" ok)" = "1" ] || fail "$scene failed: $(grep "$scene" "$work/run/results.md")"
  [ "$(value "$scene" nonfinite_pixels)" = "0" ] || fail "$scene has non-finite pixels"
done
[ "$(value high-quick counter_near_cells)" = "0" ] || fail "high above, the near band drew cells"
for scene in player-quick ant-quick; do
  near=$(value "$scene" counter_near_cells); middle=$(value "$scene" counter_middle_draws)
  far=$(value "$scene" counter_far_draws); far_cells=$(value "$scene" counter_far_cells)
  echo "$scene: near cells $near, middle draws $middle, far draws $far over $far_cells cells"
  awk -v n="$near" -v m="$middle" -v f="$far" -v fc="$far_cells" \
    'BEGIN { exit !(n > 20 && n < 2000 && m > 10 && f > 0 && f * 100 < fc) }' || fail "$scene: unexpected counts"
done
echo "OK"
