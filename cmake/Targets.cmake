# How every part declares what it builds: one call per library, program or test, so a folder's
# CMakeLists.txt says what each target is made of and links, and every target gets the same
# treatment: the warning set (Warnings.cmake), fmt, a precompiled header of fmt and the
# standard library, and the build type's flags with every sanitizer of the preset on every
# file.
#
#   l2_library(<name> [INTERFACE|OBJECT|MODULE] [HOT] [SOURCES <file>...] [COMMAND_LINE <file>...]
#              [INCLUDES <dir>...] [PRIVATE_INCLUDES <dir>...] [LINKS <item>...])
#   l2_program(<name> SOURCES <file>... [COMMAND_LINE <file>...] [PRIVATE_INCLUDES <dir>...]
#              [LINKS <item>...])
#   l2_test(<name> SOURCES <file>... [PRIVATE_INCLUDES <dir>...] [LINKS <item>...]
#           [LABELS <label>...])
#
# INCLUDES are the library's public headers (its users see them), PRIVATE_INCLUDES its own (a
# test's: the private headers of the part it tests).
# LINKS is target_link_libraries' list: PUBLIC, PRIVATE and INTERFACE keywords as there, and
# items before any keyword are PRIVATE (INTERFACE for an INTERFACE library).
#
# A static library's files are compiled together, up to 8 per unit (unity build, while
# L2_UNITY_BUILD is on, the default): each unit otherwise re-instantiates what fmt and the
# standard library leave pending. HOT keeps one
# object per file: the emulator's hot path, whose objects a test disassembles one by one and
# whose code the routing benchmark measures.
#
# Test code (l2_test) is compiled with L2_TEST_CODE_FLAGS, appended so they override the build
# type's -O: GoogleTest expands to much inline code in every test file, and optimising it was
# most of the suite's compile time, while the tests run for seconds. They do not touch the
# sanitizer flags. The libraries under test keep the build type's flags.

# A program's COMMAND_LINE files hold only its command line (CLI11, header-only in the Debian
# version, instantiated anew in every program): compiled with L2_COMMAND_LINE_FLAGS, appended,
# outside the precompiled header and the unity build. Optimising CLI11's inline code was the
# largest part of each program's build, for code that runs once at start. Sanitizer flags stay.
set(L2_COMMAND_LINE_FLAGS "-O0" CACHE STRING "Flags appended for command-line files (l2_program)")
separate_arguments(l2_command_line_flags UNIX_COMMAND "${L2_COMMAND_LINE_FLAGS}")

set(L2_TEST_CODE_FLAGS "-O0" CACHE STRING "Flags appended for test code (l2_test)")
separate_arguments(l2_test_code_flags UNIX_COMMAND "${L2_TEST_CODE_FLAGS}")

# Umbrella targets: the sanitizer runs build just the test executables they run (and what those
# depend on), not every program and benchmark.
add_custom_target(l2_asan_tests)
add_custom_target(l2_tsan_tests)

# The precompiled headers. A target may reuse one only when its flags match, so every target
# that reuses the code header links fmt (FMT_SHARED) and every test gets the same test flags.
file(WRITE ${CMAKE_BINARY_DIR}/l2_code_pch.cpp "// the precompiled header's own translation unit\n")
add_library(l2_code_pch STATIC ${CMAKE_BINARY_DIR}/l2_code_pch.cpp)
l2_warnings(l2_code_pch)
target_link_libraries(l2_code_pch PUBLIC fmt::fmt)
target_precompile_headers(l2_code_pch PRIVATE ${CMAKE_CURRENT_LIST_DIR}/pch_prelude.hpp
                          <fmt/format.h> <algorithm> <array> <chrono> <cstdint> <cstring>
                          <filesystem> <fstream> <functional> <memory> <optional> <span>
                          <stdexcept> <string> <string_view> <thread> <vector>)

if(BUILD_TESTING)
  file(WRITE ${CMAKE_BINARY_DIR}/l2_test_pch.cpp "// the precompiled header's own translation unit\n")
  add_library(l2_test_pch STATIC ${CMAKE_BINARY_DIR}/l2_test_pch.cpp)
  l2_warnings(l2_test_pch)
  target_compile_options(l2_test_pch PRIVATE ${l2_test_code_flags})
  target_link_libraries(l2_test_pch PUBLIC GTest::gtest GTest::gmock fmt::fmt)
  target_precompile_headers(l2_test_pch PRIVATE ${CMAKE_CURRENT_LIST_DIR}/pch_prelude.hpp
                            <gtest/gtest.h> <gmock/gmock.h> <fmt/format.h>
                            <algorithm> <chrono> <cstdint> <cstring> <filesystem> <fstream>
                            <memory> <optional> <stdexcept> <string> <thread> <vector>)
endif()

# target_link_libraries with items before any keyword given `default` as their scope.
function(l2_link target default)
  set(scope ${default})
  set(items)
  foreach(item ${ARGN})
    if(item MATCHES "^(PUBLIC|PRIVATE|INTERFACE)$")
      if(items)
        target_link_libraries(${target} ${scope} ${items})
      endif()
      set(scope ${item})
      set(items)
    else()
      list(APPEND items ${item})
    endif()
  endforeach()
  if(items)
    target_link_libraries(${target} ${scope} ${items})
  endif()
endfunction()

# What every compiled target of the project shares: warnings, fmt and the code header.
function(l2_common target)
  l2_warnings(${target})
  target_link_libraries(${target} PRIVATE fmt::fmt)
  target_precompile_headers(${target} REUSE_FROM l2_code_pch)
endfunction()

# The COMMAND_LINE files of a target, with the flags above.
function(l2_command_line_files target)
  if(ARGN)
    set_source_files_properties(${ARGN} TARGET_DIRECTORY ${target} PROPERTIES
                                COMPILE_OPTIONS "${l2_command_line_flags}"
                                SKIP_PRECOMPILE_HEADERS ON SKIP_UNITY_BUILD_INCLUSION ON)
  endif()
endfunction()

# A library or program links only the project's libraries defined before it: parts point down,
# so the order of the parts in the top-level CMakeLists.txt is an order in which each can be
# read knowing only those before it, and a folder's program never needs a part above it
# (tools/ holds the programs that do). Tests, which nothing links, may use any part.
function(l2_check_links_defined call name)
  foreach(item ${ARGN})
    if(item MATCHES "^l2_" AND NOT TARGET ${item})
      message(FATAL_ERROR "${call}(${name}) links ${item}, which is not defined yet: a ${call} "
                          "may link only its own part and those before it (the list of parts in "
                          "CMakeLists.txt)")
    endif()
  endforeach()
endfunction()

# A library's public header folders as its users in this build see them. Installed
# (Install.cmake), its users see the package's include folder instead: a folder of this tree
# must not be part of what the package exports.
function(l2_public_includes out)
  set(dirs)
  foreach(dir ${ARGN})
    cmake_path(ABSOLUTE_PATH dir BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} NORMALIZE)
    list(APPEND dirs $<BUILD_INTERFACE:${dir}>)
  endforeach()
  set(${out} ${dirs} PARENT_SCOPE)
endfunction()

function(l2_library name)
  cmake_parse_arguments(ARG "INTERFACE;OBJECT;MODULE;HOT" ""
                        "SOURCES;COMMAND_LINE;INCLUDES;PRIVATE_INCLUDES;LINKS" ${ARGN})
  l2_check_links_defined(l2_library ${name} ${ARG_LINKS})
  l2_public_includes(ARG_INCLUDES ${ARG_INCLUDES})
  if(ARG_INTERFACE)
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${ARG_INCLUDES})
    l2_link(${name} INTERFACE ${ARG_LINKS})
    return()
  endif()
  list(APPEND ARG_SOURCES ${ARG_COMMAND_LINE})
  if(ARG_OBJECT)
    add_library(${name} OBJECT ${ARG_SOURCES})
  elseif(ARG_MODULE)
    add_library(${name} MODULE ${ARG_SOURCES})
  else()
    add_library(${name} STATIC ${ARG_SOURCES})
    if(NOT ARG_HOT)
      set_target_properties(${name} PROPERTIES UNITY_BUILD ${L2_UNITY_BUILD})
    endif()
  endif()
  if(ARG_INCLUDES)
    target_include_directories(${name} PUBLIC ${ARG_INCLUDES})
  endif()
  if(ARG_PRIVATE_INCLUDES)
    target_include_directories(${name} PRIVATE ${ARG_PRIVATE_INCLUDES})
  endif()
  l2_link(${name} PRIVATE ${ARG_LINKS})
  l2_command_line_files(${name} ${ARG_COMMAND_LINE})
  if(ARG_MODULE OR ARG_OBJECT)
    # Loaded or linked into others with their own flags (a module's hidden visibility):
    # they parse their headers themselves.
    l2_warnings(${name})
  else()
    l2_common(${name})
  endif()
endfunction()

function(l2_program name)
  cmake_parse_arguments(ARG "" "" "SOURCES;COMMAND_LINE;PRIVATE_INCLUDES;LINKS" ${ARGN})
  l2_check_links_defined(l2_program ${name} ${ARG_LINKS})
  add_executable(${name} ${ARG_SOURCES} ${ARG_COMMAND_LINE})
  l2_command_line_files(${name} ${ARG_COMMAND_LINE})
  if(ARG_PRIVATE_INCLUDES)
    target_include_directories(${name} PRIVATE ${ARG_PRIVATE_INCLUDES})
  endif()
  l2_link(${name} PRIVATE ${ARG_LINKS})
  l2_common(${name})
endfunction()

# A GoogleTest executable registered with CTest as ONE test. Registering every test case as its
# own process cost about a second each (every binary loading its libraries at start), which
# tripled the suite; gtest still names each failing case in the output. LABELS ("asan",
# "tsan") choose the sanitizer runs the executable takes part in. Its files are compiled
# together, up to 8 per unit (each unit re-instantiates what GoogleTest, fmt and the standard
# library leave pending): two test files of one executable must not both define a helper of
# the same name.
set(L2_TEST_TMPDIR ${CMAKE_BINARY_DIR}/test-tmp)
file(MAKE_DIRECTORY ${L2_TEST_TMPDIR})

function(l2_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PRIVATE_INCLUDES;LINKS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  if(ARG_PRIVATE_INCLUDES)
    target_include_directories(${name} PRIVATE ${ARG_PRIVATE_INCLUDES})
  endif()
  l2_warnings(${name})
  target_compile_options(${name} PRIVATE ${l2_test_code_flags})
  target_precompile_headers(${name} REUSE_FROM l2_test_pch)
  set_target_properties(${name} PROPERTIES UNITY_BUILD ${L2_UNITY_BUILD})
  l2_link(${name} PRIVATE ${ARG_LINKS})
  target_link_libraries(${name} PRIVATE GTest::gtest_main GTest::gmock fmt::fmt)
  add_test(NAME ${name} COMMAND ${name} --gtest_brief=1
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  # Scratch files in a temporary folder of this build's own (TMPDIR, which
  # std::filesystem::temp_directory_path() follows): many tests name theirs by test, not by
  # process, and the suites of two checkouts run at once (a developer's and CI's) must not share
  # them.
  set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT 600
                                          ENVIRONMENT "TMPDIR=${L2_TEST_TMPDIR}")
  foreach(sanitizer asan tsan)
    if(sanitizer IN_LIST ARG_LABELS)
      add_dependencies(l2_${sanitizer}_tests ${name})
    endif()
  endforeach()
endfunction()
