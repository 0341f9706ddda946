# One place for the warning set, so every target of the project is held to the same bar.
function(l2_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion -Wnon-virtual-dtor)
  if(L2_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# Umbrella targets: the sanitizer runs build just the test executables they run (and what those
# depend on), not every program and benchmark: the ASan build of everything was a third of CI.
add_custom_target(l2_asan_tests)
add_custom_target(l2_tsan_tests)

# A GoogleTest executable registered with CTest as ONE test. Registering every test case as its
# own process cost about a second each (every binary loads OpenImageIO and its codecs), which
# tripled the suite; gtest still names each failing case in the output. LABELS ("asan",
# "tsan") choose the sanitizer runs the executable takes part in.
function(l2_gtest name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  l2_warnings(${name})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest_main GTest::gmock)
  add_test(NAME ${name} COMMAND ${name} --gtest_brief=1
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT 600)
  foreach(sanitizer asan tsan)
    if(sanitizer IN_LIST ARG_LABELS)
      add_dependencies(l2_${sanitizer}_tests ${name})
    endif()
  endforeach()
endfunction()
