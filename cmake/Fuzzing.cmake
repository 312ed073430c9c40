# CANOPY_FUZZ=ON builds the libFuzzer targets fuzz_config and fuzz_mesh (tests/fuzz/) with
# Debian's clang; every object is then instrumented for coverage, AddressSanitizer and
# UndefinedBehaviorSanitizer. Off by default: the normal build only replays the committed
# corpus (ctest fuzz_corpus:*). See tests/fuzz/README.md.
option(CANOPY_FUZZ "Build the libFuzzer targets (needs clang and libclang-rt-14-dev)" OFF)
if(CANOPY_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "CANOPY_FUZZ needs clang: configure with -DCMAKE_CXX_COMPILER=clang++ -DCANOPY_FUZZ=ON")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
  # Replaying the committed corpus once (scripts/fuzz --replay, as scripts/test does) needs the
  # checks, not the speed: unoptimised and without debug information, clang builds the targets in
  # about half the time. Fuzzing for minutes keeps the build type's -O2 -g.
  option(CANOPY_FUZZ_REPLAY_BUILD "Build the fuzz targets with -O0 -g0, for a one-off corpus replay" OFF)
  if(CANOPY_FUZZ_REPLAY_BUILD)
    add_compile_options(-O0 -g0)
  endif()
endif()
