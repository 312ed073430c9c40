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
endif()
