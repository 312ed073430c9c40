# canopy_add_doctests(SOURCES <test_*.cpp ...> [LABEL <label>] [SERIAL])
# One doctest executable per source; every TEST_CASE becomes its own ctest entry named
# "<executable>:<test case>". Tests find their data through CANOPY_TEST_DATA (tests/data) and
# the checkout through CANOPY_SOURCE_DIR, and share tests/support (canopy_test_support).
# SERIAL: ctest runs them alone (RUN_SERIAL), for tests that compare a timestamp with the wall
# clock, which other tests loading the machine would disturb.
include(${doctest_DIR}/doctest.cmake)

# Test code itself is compiled -O1 in Release: what the tests time and check is canopy_core and
# the techniques, built -O3 as the canopy command is, and -O1 compiles them in 40 % less time
# (GCC 12: test_config 19.0 s at -O3, 11.9 s at -O1).
# The sanitizer build (cmake/Sanitize.cmake, -O1) compiles test code -O0: ASan's instrumentation
# makes -O1 dear (test_metric_registry 20.4 s at -O1, 12.7 s at -O0), and CI builds every test twice.
if(CANOPY_SANITIZE)
  set(canopy_test_compile_options -O0)
else()
  set(canopy_test_compile_options $<$<CONFIG:Release>:-O1>)
endif()

function(canopy_add_doctests)
  cmake_parse_arguments(ARG "SERIAL" "LABEL" "SOURCES" ${ARGN})
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(name ${src} NAME_WE)
    add_executable(${name} ${src})
    target_link_libraries(${name} PRIVATE canopy_core canopy_techniques canopy_test_support)
    target_compile_options(${name} PRIVATE ${canopy_test_compile_options})
    target_compile_definitions(${name} PRIVATE CANOPY_TEST_DATA="${PROJECT_SOURCE_DIR}/tests/data"
                                               CANOPY_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
    doctest_discover_tests(${name} TEST_PREFIX "${name}:")
    # Labels and RUN_SERIAL are set by a file ctest includes after doctest's list of the tests
    # (<name>_TESTS): passed through doctest_discover_tests' PROPERTIES, a list of labels loses
    # its escaping and doctest appends an empty LABELS of its own, so `ctest -L <family>` found
    # nothing.
    set(labels ${name})
    if(ARG_LABEL)
      list(APPEND labels ${ARG_LABEL})
    endif()
    set(serial "")
    if(ARG_SERIAL)
      set(serial " RUN_SERIAL TRUE")
    endif()
    set(properties_file ${CMAKE_CURRENT_BINARY_DIR}/${name}_properties.cmake)
    file(WRITE ${properties_file}
         "if(DEFINED ${name}_TESTS)\n  set_tests_properties(\${${name}_TESTS} PROPERTIES LABELS \"${labels}\"${serial})\nendif()\n")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${properties_file})
  endforeach()
endfunction()
