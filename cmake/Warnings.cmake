# One place for the warning set, so every target of the project is held to the same bar.
function(l2_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion -Wnon-virtual-dtor)
  if(L2_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# A test executable registered with CTest through GoogleTest discovery.
# LABELS lets the sanitizer runs pick the suites that matter to them.
function(l2_gtest name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  l2_warnings(${name})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest_main GTest::gmock)
  # CMake 3.25 flattens discovered tests' properties, so a label list "asan;tsan" loses its
  # second label. Join the labels into one ("asan-tsan"): CTest's -L takes a regular
  # expression, so both "-L asan" and "-L tsan" still select the test.
  list(JOIN ARG_LABELS "-" labels)
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 DISCOVERY_MODE PRE_TEST
                       PROPERTIES LABELS "${labels}"
                       WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endfunction()
