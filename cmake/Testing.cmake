# canopy_add_doctests(SOURCES <test_*.cpp ...> [LABEL <label>] [SERIAL])
# One doctest executable per source; every TEST_CASE becomes its own ctest entry named
# "<executable>:<test case>". Tests find their data through CANOPY_TEST_DATA (tests/data) and
# the checkout through CANOPY_SOURCE_DIR, and share tests/support (canopy_test_support).
# SERIAL: ctest runs them alone (RUN_SERIAL), for tests that compare a timestamp with the wall
# clock, which other tests loading the machine would disturb.
include(${doctest_DIR}/doctest.cmake)

# Test code itself is compiled -O1 in Release: what the tests time and check is canopy_core and
# the techniques, built -O3 as the canopy command is, and -O1 compiles them in 40 % less time (GCC 12: test_config 19.0 s at -O3, 11.9 s at -O1).
set(canopy_test_compile_options $<$<CONFIG:Release>:-O1>)

function(canopy_add_doctests)
  cmake_parse_arguments(ARG "SERIAL" "LABEL" "SOURCES" ${ARGN})
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(name ${src} NAME_WE)
    add_executable(${name} ${src})
    target_link_libraries(${name} PRIVATE canopy_core canopy_techniques canopy_test_support)
    target_compile_options(${name} PRIVATE ${canopy_test_compile_options})
    target_compile_definitions(${name} PRIVATE CANOPY_TEST_DATA="${PROJECT_SOURCE_DIR}/tests/data"
                                               CANOPY_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
    set(labels ${name})
    if(ARG_LABEL)
      list(APPEND labels ${ARG_LABEL})
    endif()
    set(properties LABELS "${labels}")
    if(ARG_SERIAL)
      list(APPEND properties RUN_SERIAL TRUE)
    endif()
    doctest_discover_tests(${name} TEST_PREFIX "${name}:" PROPERTIES ${properties})
  endforeach()
endfunction()
