# Links with LLVM's lld where it is installed (Debian's lld, scripts/install-deps): every test is
# its own executable that links canopy_core and every technique, about 85 links a build, and lld
# links one in a third of the time GNU ld takes (test_config with ASan: 4.4 s against 1.9 s, its
# test discovery included). CANOPY_LINKER=default keeps the compiler's own.
set(CANOPY_LINKER "lld" CACHE STRING "Linker: lld (when the compiler accepts -fuse-ld=lld) or default")
if(CANOPY_LINKER STREQUAL "lld")
  include(CheckLinkerFlag)
  check_linker_flag(CXX -fuse-ld=lld canopy_have_lld)
  if(canopy_have_lld)
    add_link_options(-fuse-ld=lld)
  else()
    message(STATUS "canopy: lld not found; linking with the compiler's default linker (scripts/install-deps installs lld)")
  endif()
endif()
