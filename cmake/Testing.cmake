# canopy_add_doctests(SOURCES <test_*.cpp ...> [LABEL <label>])
# One doctest executable per source; every TEST_CASE becomes its own ctest entry named
# "<executable>:<test case>". Tests find their data through CANOPY_TEST_DATA (tests/data) and
# the checkout through CANOPY_SOURCE_DIR, and share tests/support (canopy_test_support).
include(${doctest_DIR}/doctest.cmake)

function(canopy_add_doctests)
  cmake_parse_arguments(ARG "" "LABEL" "SOURCES" ${ARGN})
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(name ${src} NAME_WE)
    add_executable(${name} ${src})
    target_link_libraries(${name} PRIVATE canopy_core canopy_techniques canopy_test_support)
    target_compile_definitions(${name} PRIVATE CANOPY_TEST_DATA="${PROJECT_SOURCE_DIR}/tests/data"
                                               CANOPY_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
    set(labels ${name})
    if(ARG_LABEL)
      list(APPEND labels ${ARG_LABEL})
    endif()
    doctest_discover_tests(${name} TEST_PREFIX "${name}:" PROPERTIES LABELS "${labels}")
  endforeach()
endfunction()
