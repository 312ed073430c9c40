#!/usr/bin/env bash
# Inputs that crashed canopy, wrote outside its run folder or failed late (issue 7, section 4):
# each must exit 2 with file:line and nothing written, or (an empty scene) complete normally.
# Usage: bad_input.sh CANOPY DATA_DIR CASE
set -uo pipefail
canopy=$1 data=$2 case=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
mkdir -p "$work/scenes" "$work/experiments"

# scene SCENE_NAME LIGHT_LINES OBJECT_LINES: writes scenes/SCENE_NAME.toml.
scene() {
  printf '[camera]\nposition = [0, 4, 6]\n\n[[light]]\n%b\n\n[[object]]\nshape = "plane"\n\n%b\n' "$2" "$3" >"$work/scenes/$1.toml"
}
# experiment NAME SCENE [TECHNIQUE_LINES]: writes experiments/NAME.toml over ../scenes/SCENE.toml.
experiment() {
  printf '[experiment]\nscenes = ["../scenes/%s.toml"]\nresolutions = [[32, 24]]\nwarmup = 0\nrepetitions = 1\n\n%b\n' \
    "$2" "${3:-[[technique]]\nname = \"shadow.hard\"}" >"$work/experiments/$1.toml"
}
# expect_refused EXPERIMENT REGEX: exit 2, the message matches, and no output folder.
expect_refused() {
  "$canopy" run "$work/experiments/$1.toml" --out "$work/out" --no-cache >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  cat "$work/stderr"
  [ $rc -eq 2 ] || fail "$1: exit code $rc, expected 2"
  grep -Eq -- "$2" "$work/stderr" || fail "$1: message does not match '$2'"
  [ ! -e "$work/out" ] || fail "$1: an output folder was created for a bad input"
}
directional='type = "directional"\nintensity = 2'
box='[[object]]\nshape = "box"\ntranslate = [0, 1, 0]'

case $case in
  empty_scene)
    # Before: segfault on a zero-size vertex buffer, after results.json was written.
    printf '[scene]\nname = "empty"\nbackground = 0.5\n\n[[light]]\ntype = "directional"\n' >"$work/scenes/empty.toml"
    experiment empty empty
    "$canopy" run "$work/experiments/empty.toml" --out "$work/out" --no-cache --no-progress >"$work/stdout" 2>"$work/stderr" \
      || fail "run of an empty scene failed: $(cat "$work/stderr")"
    python3 -c "import json,sys; j=json.load(open('$work/out/results.json')); sys.exit(0 if j['status']=='complete' and len(j['cases'])==1 else 1)" \
      || fail "results.json is not a complete record of one case"
    [ -s "$work/out/images/empty_32x24_shadow.hard.png" ] || fail "missing the case image"
    [ -s "$work/out/images/reference_empty_32x24.png" ] || fail "missing the reference image" ;;
  bad_ply)
    # Before: heap corruption inside assimp (free(): invalid next size).
    scene ply "$directional" "[[object]]\nshape = \"mesh\"\nfile = \"$data/bad_input/meshes/face_index_out_of_range.ply\""
    experiment ply ply
    expect_refused ply 'scenes/ply\.toml:11: error: .*face_index_out_of_range\.ply.*out of range' ;;
  assimp_crash)
    # A crash inside assimp (simulated by the test hook) is a config error, not a crash of canopy.
    scene crash "$directional" '[[object]]\nshape = "mesh"\nfile = "/usr/share/assimp/models/OBJ/box.obj"'
    experiment crash crash
    CANOPY_TEST_MESH_IMPORT_SIGNAL=11 expect_refused crash 'scenes/crash\.toml:11: error: .*assimp crashed while reading .*box\.obj.*signal 11' ;;
  scene_name)
    # Before: the reference images were written three folders above the run folder.
    printf '[scene]\nname = "../../../x"\n\n[[light]]\ntype = "directional"\n\n[[object]]\nshape = "box"\n' >"$work/scenes/escape.toml"
    experiment escape escape
    expect_refused escape 'scenes/escape\.toml:2: error: the scene name .*\.\.' 
    [ -z "$(find "$work" -name 'x_*')" ] || fail "files named after the scene were written"
    "$canopy" reference "$work/scenes/escape.toml" --out "$work/ref/a/b" --width 8 --height 8 --no-cache 2>"$work/stderr"
    [ $? -eq 2 ] || fail "canopy reference accepted the name"
    [ ! -e "$work/ref" ] || fail "canopy reference wrote something"
    # A name in another script is fine and keeps readable file names.
    printf '[scene]\nname = "forêt_森"\n\n[[light]]\ntype = "directional"\n\n[[object]]\nshape = "box"\n' >"$work/scenes/forest.toml"
    "$canopy" reference "$work/scenes/forest.toml" --out "$work/ref" --width 8 --height 8 --light-samples 1 --pixel-samples 1 --no-cache >/dev/null \
      || fail "canopy reference refused a unicode name"
    [ -s "$work/ref/forêt_森_8x8.png" ] || fail "the unicode name's image is missing" ;;
  mesh_dir)
    # Before: "not found".
    scene folder "$directional" "[[object]]\nshape = \"mesh\"\nfile = \"$data/bad_input/meshes/a_folder.obj\""
    experiment folder folder
    expect_refused folder 'scenes/folder\.toml:13: error: .*a_folder\.obj.* is a directory' ;;
  float_limits)
    # Before: failed at reference time after files were written, or a PSNR of -696 dB.
    scene huge 'type = "directional"\nintensity = 1e39' "$box"
    experiment huge huge
    expect_refused huge 'scenes/huge\.toml:6: error: .*intensity.*single-precision'
    scene bright 'type = "directional"\nintensity = 3e38' "$box"
    experiment bright bright
    expect_refused bright 'scenes/bright\.toml:6: error: .*intensity.* must lie in \[0, 1000000\]'
    scene tiny "$directional" "$box\nscale = 1e-30"
    experiment tiny tiny
    expect_refused tiny 'scenes/tiny\.toml:14: error: .*scale.*\[0\.001, 1000\]'
    scene far "$directional" '[[object]]\nshape = "box"\ntranslate = [1e30, 0, 0]'
    experiment far far
    expect_refused far 'scenes/far\.toml:13: error: .*translate.*coordinate range' ;;
  refused_cases)
    # Before: only the first refused case, and "pick another device" for a missing area light.
    scene point "$directional" "$box"
    experiment point point '[[technique]]\nname = "shadow.pcss"\n[technique.params]\nkernel = [3, 5, 7]\n\n[[technique]]\nname = "shadow.ssss"'
    expect_refused point 'experiments/point\.toml:7: error: 4 of 4 cases cannot run'
    [ "$(grep -c 'needs an area light' "$work/stderr")" -eq 4 ] || fail "not every refused case is listed"
    grep -q 'hint: give the shadow light a size' "$work/stderr" || fail "the hint does not fit a missing area light"
    ! grep -q -- '--device' "$work/stderr" || fail "the hint suggests another device for a scene problem" ;;
  bench_ranges)
    # Before: segfault, out of device memory, a table of zeros with R² 1.000.
    for args in "scaling --width 0" "scaling --width -5" "scaling --height 9000" "scaling --measured 0" \
                "scaling --measured -1" "reference --width 0" "reference --light-samples 0" "reference --pixel-samples 2000"; do
      # shellcheck disable=SC2086
      "$canopy" bench $args >"$work/stdout" 2>"$work/stderr"
      rc=$?
      cat "$work/stderr"
      [ $rc -eq 2 ] || fail "bench $args: exit code $rc, expected 2"
      grep -Eq 'not in range [0-9]+ to [0-9]+' "$work/stderr" || fail "bench $args: the message gives no valid range"
    done ;;
  bench_default_scene)
    # Before: an absolute path of the build machine's checkout was compiled into the binary.
    "$canopy" bench reference --help >"$work/help" || fail "bench reference --help failed"
    grep -q "configs/scenes/spheres.toml in the current directory" "$work/help" || fail "--help does not say where the default scene is looked for"
    # From any folder, the scene of the checkout the binary was built in (build/canopy -> ../configs).
    (cd "$work" && "$canopy" bench reference --width 8 --height 8 --light-samples 1 --pixel-samples 1 >"$work/stdout" 2>"$work/stderr") \
      || fail "bench reference did not find the default scene: $(cat "$work/stderr")"
    grep -q "on spheres at 8x8" "$work/stderr" || fail "bench reference did not use spheres.toml"
    # A binary outside a checkout, run outside a checkout: the scene is required.
    mkdir -p "$work/elsewhere"
    cp "$canopy" "$work/elsewhere/canopy"
    (cd "$work/elsewhere" && ./canopy bench reference >"$work/stdout" 2>"$work/stderr"); rc=$?
    cat "$work/stderr"
    [ $rc -eq 2 ] || fail "exit code $rc without a scene, expected 2"
    grep -q "no scene given" "$work/stderr" || fail "the message does not say a scene is needed"
    # The current directory's configs/ comes first.
    mkdir -p "$work/elsewhere/configs/scenes"
    printf '[scene]\nname = "local"\n[[light]]\ntype = "directional"\n[[object]]\nshape = "box"\n' >"$work/elsewhere/configs/scenes/spheres.toml"
    (cd "$work/elsewhere" && ./canopy bench reference --width 8 --height 8 --light-samples 1 --pixel-samples 1 >/dev/null 2>"$work/stderr") \
      || fail "bench reference failed with configs/ in the current directory"
    grep -q "on local at 8x8" "$work/stderr" || fail "the current directory's configs/ was not used" ;;
  tile_hint)
    # Issue 36: `--tile 0/8` was answered with an example of --shard.
    "$canopy" reference "$data/scenes/tiny.toml" --tile 0/8 --out "$work/tiles" --width 8 --height 8 >"$work/stdout" 2>"$work/stderr"
    rc=$?
    cat "$work/stderr"
    [ $rc -eq 2 ] || fail "exit code $rc, expected 2"
    grep -q -- '--tile 0/8: i must be 1 to N .*e\.g\. --tile 1/8' "$work/stderr" || fail "the message does not give --tile's form"
    ! grep -q -- '--shard' "$work/stderr" || fail "the message names --shard"
    [ ! -e "$work/tiles" ] || fail "a tile folder was created" ;;
  scene_dir)
    # Issue 36: a scene path naming a folder said "not found".
    experiment folder_scene unused
    sed -i 's|"../scenes/unused.toml"|"../scenes"|' "$work/experiments/folder_scene.toml"
    expect_refused folder_scene "experiments/folder_scene\.toml:2: error: scene file '\.\./scenes' is a directory" ;;
  unknown_command)
    # Issue 36: `canopy frobnicate` said "A subcommand is required".
    "$canopy" frobnicate >"$work/stdout" 2>"$work/stderr"
    rc=$?
    cat "$work/stderr"
    [ $rc -eq 2 ] || fail "exit code $rc, expected 2"
    grep -q 'unknown command frobnicate; the commands are: run, reference, bench, compare' "$work/stderr" \
      || fail "the message does not name the word and list the commands"
    "$canopy" bench refrence >"$work/stdout" 2>"$work/stderr"
    rc=$?
    cat "$work/stderr"
    [ $rc -eq 2 ] || fail "bench refrence: exit code $rc, expected 2"
    grep -q "unknown command bench refrence; the commands are: reference, scaling" "$work/stderr" || fail "bench's commands are not listed"
    grep -q "did you mean bench reference?" "$work/stderr" || fail "no suggestion" ;;
  cache_dir_file)
    # Issue 36: CANOPY_CACHE_DIR naming a file was found only after ray-tracing. A reference that
    # takes minutes must be refused at once.
    echo "a file" >"$work/cache_file"
    start=$(date +%s)
    CANOPY_CACHE_DIR="$work/cache_file" timeout 60 "$canopy" reference "$data/scenes/tiny.toml" --out "$work/ref" \
      --width 2048 --height 2048 --pixel-samples 256 >"$work/stdout" 2>"$work/stderr"
    rc=$?
    cat "$work/stderr"
    [ $rc -eq 2 ] || fail "reference: exit code $rc, expected 2"
    [ $(($(date +%s) - start)) -le 10 ] || fail "refused only after $(($(date +%s) - start)) s"
    grep -q "$work/cache_file: error: is a file, not a folder.*CANOPY_CACHE_DIR names it" "$work/stderr" || fail "the message does not name the file"
    [ ! -e "$work/ref" ] || fail "reference wrote something"
    # The same through --reference-cache, and in a run; a run without the reference does not need the cache.
    "$canopy" reference "$data/scenes/tiny.toml" --reference-cache "$work/cache_file/reference" --width 8 --height 8 >/dev/null 2>"$work/stderr"
    rc=$?
    [ $rc -eq 2 ] && grep -q "is a file, not a folder" "$work/stderr" || fail "--reference-cache through a file: exit $rc"
    CANOPY_CACHE_DIR="$work/cache_file" "$canopy" run "$data/experiments/tiny.toml" --out "$work/out" --quick >/dev/null 2>"$work/stderr"
    rc=$?
    [ $rc -eq 2 ] && grep -q "is a file, not a folder" "$work/stderr" || fail "run: exit $rc, expected 2"
    [ ! -e "$work/out" ] || fail "the run created its folder"
    CANOPY_CACHE_DIR="$work/cache_file" "$canopy" run "$data/experiments/tiny.toml" --out "$work/out" --quick --no-reference \
      --images none --no-progress >/dev/null 2>"$work/stderr" || fail "run --no-reference refused: $(cat "$work/stderr")" ;;
  density_map_file)
    # Issue 36: an image that is not one exited 1 with no file:line.
    printf '[scene]\nname = "lawn"\n\n[[light]]\ntype = "directional"\ndirection = [0, -1, 0]\n\n[[object]]\nshape = "plane"\nsize = [8, 8]\n\n[[population]]\nname = "lawn"\nkind = "grass"\nparams = { cells_x = 2, cells_z = 2, cell_size = 1, blades = 20, density_map = "file", density_map_file = "map.png" }\n' \
      >"$work/scenes/lawn.toml"
    experiment lawn lawn
    echo "not an image" >"$work/scenes/map.png"
    expect_refused lawn 'scenes/lawn\.toml:12: error: .*density_map_file: cannot read image .*map\.png: it is neither PNG nor OpenEXR'
    printf '\x89PNG\r\n\x1a\ntruncated' >"$work/scenes/map.png"
    expect_refused lawn 'scenes/lawn\.toml:12: error: .*density_map_file: cannot read image .*map\.png: ' ;;
  repeated_entries)
    # Issue 36: the same scene or technique listed twice gave identical rows under one heading.
    scene box "$directional" "$box"
    printf '[experiment]\nscenes = [\n  "../scenes/box.toml",\n  "../scenes/box.toml",\n]\nresolutions = [[32, 24]]\n\n[[technique]]\nname = "shadow.hard"\n' \
      >"$work/experiments/scene_twice.toml"
    expect_refused scene_twice 'experiments/scene_twice\.toml:4: error: scene .box. is listed twice \(first at line 3\)'
    grep -q 'hint: .*variant with a name of its own' "$work/stderr" || fail "no hint for a repeated scene"
    pcf3='[[technique]]\nname = "shadow.pcf"\n[technique.params]\nkernel = 3'
    experiment technique_twice box "$pcf3\n\n[[technique]]\nname = \"shadow.hard\"\n\n[[technique]]\nname = \"shadow.pcf\"\nparams = { kernel = 3 }"
    expect_refused technique_twice 'experiments/technique_twice\.toml:15: error: \[\[technique\]\] shadow\.pcf repeats the parameters of the \[\[technique\]\] at line 7 \(.* kernel=3 '
    grep -q 'hint: remove this entry, or give it other parameters' "$work/stderr" || fail "no hint for a repeated technique"
    # Sweeps that overlap, and a list holding a value twice, repeat cases too.
    experiment overlap box '[[technique]]\nname = "shadow.pcf"\nparams = { kernel = [3, 5] }\n\n[[technique]]\nname = "shadow.pcf"\nparams = { kernel = [5, 7] }'
    expect_refused overlap 'experiments/overlap\.toml:11: error: .*repeats the parameters of the \[\[technique\]\] at line 7 \(.* kernel=5 '
    experiment listed_twice box '[[technique]]\nname = "shadow.pcf"\nparams = { kernel = [3, 3] }'
    expect_refused listed_twice 'experiments/listed_twice\.toml:7: error: .*shadow\.pcf gives the same parameters twice'
    # Another parameter, or a variant of the scene with its own name, is another case.
    experiment kernels box "$pcf3\n\n[[technique]]\nname = \"shadow.pcf\"\nparams = { kernel = 5 }"
    sed -i 's|scenes = .*|scenes = ["../scenes/box.toml", { file = "../scenes/box.toml", name = "box-b" }]|' "$work/experiments/kernels.toml"
    "$canopy" plan "$work/experiments/kernels.toml" >"$work/stdout" 2>"$work/stderr" || fail "distinct entries refused: $(cat "$work/stderr")"
    grep -q "4 cases" "$work/stdout" || fail "expected 4 cases: $(head -1 "$work/stdout")" ;;
  *) fail "unknown case $case" ;;
esac
echo "ok: $case"
