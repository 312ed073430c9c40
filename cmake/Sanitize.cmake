# CANOPY_SANITIZE=ON (scripts/build Sanitize, into build-sanitize/): AddressSanitizer and
# UndefinedBehaviorSanitizer, every UB report fatal, and every local variable the code leaves
# uninitialised filled with a pattern. ASan and UBSan do not see reads of uninitialised memory;
# the pattern (clang: 0xAA.. for integers and pointers, NaN for floats) turns one into a value
# that misbehaves loudly, e.g. a ray lane Embree rejects. -O1 -g0 keeps the build cheap; frame
# pointers keep ASan's stacks readable without debug info. -ffp-contract=off: clang otherwise
# fuses a * b + c into one rounding (even when constant folding, with no FMA unit in the target),
# while GCC in ISO C++ mode (the Release build) does not; tests that pin exact float results
# must see the same arithmetic in both builds.
option(CANOPY_SANITIZE "Build with ASan + UBSan (fatal) and pattern-initialised locals" OFF)

if(CANOPY_SANITIZE)
  set(canopy_sanitizers -fsanitize=address,undefined -fno-sanitize-recover=all)
  add_compile_options(${canopy_sanitizers} -ftrivial-auto-var-init=pattern -fno-omit-frame-pointer
                      -ffp-contract=off -O1 -g0)
  add_link_options(${canopy_sanitizers})
endif()
