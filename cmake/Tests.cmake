# Umbrella targets: the sanitizer runs build just the test executables they run (and what those
# depend on), not every program and benchmark: the ASan build of everything was a third of CI.
add_custom_target(l2_asan_tests)
add_custom_target(l2_tsan_tests)

# One precompiled header for every test executable: with test code built light, parsing
# GoogleTest, fmt and the standard library was most of a test file's compile time. A target
# may reuse it only with the same flags, so every test gets the same light flags and fmt.
file(WRITE ${CMAKE_BINARY_DIR}/l2_test_pch.cpp "// the precompiled header's own translation unit\n")
add_library(l2_test_pch STATIC ${CMAKE_BINARY_DIR}/l2_test_pch.cpp)
l2_warnings(l2_test_pch)
target_compile_options(l2_test_pch PRIVATE ${l2_light_code_flags})
target_link_libraries(l2_test_pch PUBLIC GTest::gtest GTest::gmock fmt::fmt)
target_precompile_headers(l2_test_pch PRIVATE ${CMAKE_CURRENT_LIST_DIR}/pch_prelude.hpp
                          <gtest/gtest.h> <gmock/gmock.h> <fmt/format.h>
                          <algorithm> <chrono> <cstdint> <cstring> <filesystem> <fstream>
                          <memory> <optional> <stdexcept> <string> <thread> <vector>)

# A GoogleTest executable registered with CTest as ONE test. Registering every test case as its
# own process cost about a second each (every binary then loaded OpenImageIO and its codecs at
# start; now only on its first picture, image/src/png_codec.hpp), which tripled the suite; gtest
# still names each failing case in the output. LABELS ("asan", "tsan") choose the sanitizer runs
# the executable takes part in.
function(l2_gtest name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  l2_warnings(${name})
  target_compile_options(${name} PRIVATE ${l2_light_code_flags})
  target_precompile_headers(${name} REUSE_FROM l2_test_pch)
  # A test executable's files are compiled together (up to 8 per unit): each unit re-instantiates
  # the templates GoogleTest, fmt and the standard library leave pending, about 1.2 s even with the
  # precompiled header. Release build, same minutes: test compile time 180 -> 124 s of CPU. Two
  # test files of one executable must not both define a helper of the same name.
  set_target_properties(${name} PROPERTIES UNITY_BUILD ON)
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest_main GTest::gmock fmt::fmt)
  add_test(NAME ${name} COMMAND ${name} --gtest_brief=1
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT 600)
  foreach(sanitizer asan tsan)
    if(sanitizer IN_LIST ARG_LABELS)
      add_dependencies(l2_${sanitizer}_tests ${name})
    endif()
  endforeach()
endfunction()
