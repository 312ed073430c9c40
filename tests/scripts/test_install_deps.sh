#!/usr/bin/env bash
# scripts/demo installs and builds only what the demo needs: `install-deps --demo` holds every
# package CMakeLists.txt's find_package calls need and none of the test tools; scripts/test installs
# everything. Usage: test_install_deps.sh CHECKOUT
set -euo pipefail
root=$1
fail() { echo "FAIL: $*"; exit 1; }
demo=$("$root/scripts/install-deps" --demo --print)
full=$("$root/scripts/install-deps" --print)
for p in $demo; do grep -qx "$p" <<<"$full" || fail "$p is in the demo's packages but not in the full list"; done
for p in chromium slurm-wlm munge clang vulkan-validationlayers python3-matplotlib openimageio-tools lld; do
  ! grep -qx "$p" <<<"$demo" || fail "the demo installs $p, a test tool"
  grep -qx "$p" <<<"$full" || fail "scripts/test no longer installs $p"
done
# Each package CMakeLists.txt finds, by the Debian package that provides it.
declare -A provides=([Vulkan]=libvulkan-dev [OpenEXR]=libopenexr-dev [PNG]=libpng-dev [embree]=libembree-dev
  [tomlplusplus]=libtomlplusplus-dev [doctest]=doctest-dev [fmt]=libfmt-dev [CLI11]=libcli11-dev
  [nlohmann_json]=nlohmann-json3-dev [glm]=libglm-dev [assimp]=libassimp-dev [Threads]=build-essential)
for found in $(sed -n 's/^ *find_package(\([A-Za-z0-9_]*\).*/\1/p' "$root/CMakeLists.txt"); do
  [ -n "${provides[$found]:-}" ] || fail "CMakeLists.txt finds $found: name its Debian package in this test"
  grep -qx "${provides[$found]}" <<<"$demo" || fail "the demo does not install ${provides[$found]} (for $found)"
done
grep -q '^scripts/install-deps --demo$' "$root/scripts/demo" || fail "scripts/demo does not install the demo's packages alone"
grep -q '^scripts/build Release canopy$' "$root/scripts/demo" || fail "scripts/demo does not build canopy alone"
grep -q '^scripts/install-deps$' "$root/scripts/test" || fail "scripts/test does not install everything"
echo "install-deps: ok ($(wc -w <<<"$demo") packages for the demo, $(wc -w <<<"$full") for the tests)"
