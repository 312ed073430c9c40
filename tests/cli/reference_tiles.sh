#!/usr/bin/env bash
# canopy reference --tile i/N and --merge-tiles N (issue 12): a reference rendered as 3 row bands
# by separate processes and merged into the cache equals, pixel for pixel in every image (radiance,
# variance, visibility, pixel-centre visibility), the same reference rendered whole; a missing
# tile is named.
# Usage: reference_tiles.sh CANOPY DATA_DIR
set -uo pipefail
canopy=$1
data=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
scene="$data/scenes/tiny.toml"
# 50 rows: bands of 16, 17 and 17 rows, not aligned with the renderer's 16-pixel tiles.
size=(--width 40 --height 50 --light-samples 8 --pixel-samples 2)
"$canopy" reference "$scene" "${size[@]}" --no-cache --out "$work/whole" >/dev/null || fail "whole render failed"
for i in 1 2 3; do
  "$canopy" reference "$scene" "${size[@]}" --tile "$i/3" --out "$work/tiles" >"$work/tile-$i" 2>&1 || fail "tile $i/3 failed: $(cat "$work/tile-$i")"
done
grep -q "merge-tiles 3" "$work/tile-3" || fail "a tile does not say how to merge"
# Two tiles of three: refused, naming the missing one; nothing reaches the cache.
mkdir -p "$work/two"
cp "$work"/tiles/*tile-1-of-3* "$work"/tiles/*tile-2-of-3* "$work/two/"
"$canopy" reference "$scene" "${size[@]}" --merge-tiles 3 --out "$work/two" --reference-cache "$work/cache" 2>"$work/err"
[ $? -eq 2 ] && grep -q "3/3" "$work/err" || fail "a missing tile: $(cat "$work/err")"
[ -z "$(ls -A "$work/cache" 2>/dev/null)" ] || fail "a partial merge wrote into the cache"
"$canopy" reference "$scene" "${size[@]}" --merge-tiles 3 --out "$work/tiles" --reference-cache "$work/cache" >"$work/merged" \
  2>&1 || fail "merge failed: $(cat "$work/merged")"
grep -q "(from cache" "$work/merged" || fail "the merged reference was not taken from the cache: $(cat "$work/merged")"
for f in tiny_40x50.exr tiny_40x50.variance.exr tiny_40x50.visibility.exr tiny_40x50.pixel_visibility.exr; do
  idiff -fail 0 -failpercent 0 -warn 0 "$work/whole/$f" "$work/tiles/$f" >"$work/idiff" 2>&1 \
    || fail "$f differs from the whole render: $(cat "$work/idiff")"
done
# Not a vacuous comparison: the images hold light and shadow.
oiiotool --stats "$work/tiles/tiny_40x50.exr" | grep -q "Max: *[0-9]*\.[0-9]*[1-9]" || fail "the merged radiance is black"
echo "reference tiles: ok"
