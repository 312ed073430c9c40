# CANOPY_SANITIZE=ON (scripts/build Sanitize, into build-sanitize/, with GCC): AddressSanitizer
# and UndefinedBehaviorSanitizer, every UB report fatal, and every local variable the code leaves
# uninitialised filled with a pattern. ASan and UBSan do not see reads of uninitialised memory;
# GCC's pattern (0xFE bytes: -1.7e38 as a float) turns one into a value that misbehaves loudly,
# e.g. a ray lane whose origin Embree's assertions reject. (clang's pattern makes floats NaN,
# which Embree silently drops as an inactive lane: measured, see scripts/build.) -O1 -g0 keeps
# the build cheap; frame pointers keep ASan's stacks readable without debug info. GCC 12 warns
# "used uninitialized" about its own pattern stores in fmt's and libstdc++'s headers (false
# positives): those two warnings stay on in the Release build only.
option(CANOPY_SANITIZE "Build with ASan + UBSan (fatal) and pattern-initialised locals" OFF)

if(CANOPY_SANITIZE)
  # float-cast-overflow (a float out of an integer's range, NaN included, converted to it) is UB
  # that GCC's -fsanitize=undefined leaves out.
  set(canopy_sanitizers -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all)
  add_compile_options(${canopy_sanitizers} -ftrivial-auto-var-init=pattern -fno-omit-frame-pointer -O1 -g0
                      -Wno-uninitialized -Wno-maybe-uninitialized)
  add_link_options(${canopy_sanitizers})
endif()
