# `l2wall golden check|update`: golden-image regression of reassembly. The images and their
# manifest are in tests/golden_images/ (README.md there); this library reproduces them.
find_package(PkgConfig REQUIRED)
pkg_check_modules(TOMLPP REQUIRED IMPORTED_TARGET tomlplusplus)

l2_library(l2_golden
           SOURCES src/golden/golden_manifest.cpp src/golden/golden_routing.cpp
                   src/golden/golden_rendered.cpp src/golden/golden_entry.cpp
                   src/golden/golden_check.cpp src/golden/golden_update.cpp
           COMMAND_LINE src/golden_command.cpp
           PRIVATE_INCLUDES src
           LINKS PUBLIC l2_wallrun l2_tilelayout l2_image l2_pipeserver l2_strip_headers fmt::fmt
                 PRIVATE l2_picture_files l2_folders l2_wall_file l2_emu l2_vizserver PkgConfig::TOMLPP l2_command_line)
# The default golden folder, wall paths and pipeserver are found where l2wall runs from
# (command_line/program_paths.hpp): the installed tree or the working tree of the build.
add_dependencies(l2_golden pipeserver)
target_link_libraries(l2wall PRIVATE l2_golden)

if(BUILD_TESTING)
  # Pictures, manifest, in-process routing of the test pattern: fast, also under ASan.
  l2_test(l2wall_golden_tests PRIVATE_INCLUDES src
          SOURCES tests/golden_compare_test.cpp tests/golden_manifest_test.cpp
                  tests/golden_routing_test.cpp
          LINKS l2_golden l2_emu l2_wall_file l2_pipeserver_lsan LABELS "asan")
  target_compile_definitions(l2wall_golden_tests PRIVATE L2_SOURCE_DIR="${L2_SOURCE_DIR}")
  # `l2wall golden` as users run it, on temporary copies of the golden folder: a changed golden
  # pixel, a changed header field in a captured frame, refused updates, idiff's verdict; and,
  # apart because its live runs take longest, a rendered entry made by another Mesa.
  foreach(kind cli cli_rendered)
    l2_test(l2wall_golden_${kind}_tests SOURCES tests/golden_${kind}_test.cpp PRIVATE_INCLUDES src
            LINKS l2_golden l2_tilelayout l2_wall_file l2_image l2_picture_files l2_strip_headers)
    target_compile_definitions(l2wall_golden_${kind}_tests PRIVATE
                               L2WALL_PATH="$<TARGET_FILE:l2wall>"
                               TILELAYOUT_PATH="$<TARGET_FILE:tilelayout>"
                               L2_SOURCE_DIR="${L2_SOURCE_DIR}")
    add_dependencies(l2wall_golden_${kind}_tests l2wall pipeserver tilelayout)
  endforeach()
  # The repository's golden images, every entry.
  add_test(NAME l2wall_golden_check
           COMMAND l2wall golden check --out ${CMAKE_CURRENT_BINARY_DIR}/golden-check)
  set_tests_properties(l2wall_golden_check PROPERTIES TIMEOUT 180)
endif()
