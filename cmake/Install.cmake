# `cmake --install`: the programs into PREFIX/bin; what they find by default beside them
# (command_line/program_paths.hpp) into PREFIX/share/lightning2: the example walls, the bunny of
# the mesh scene and the golden images with their manifest; the documentation into
# PREFIX/share/doc/lightning2.
include(GNUInstallDirs)
set(l2_installed_programs l2wall pipeserver vizserver lightning2_emu tilelayout strip_headers
                          sync_backchannel show_wall)
install(TARGETS ${l2_installed_programs} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# The image codec module every program loads on its first picture (image/src/png_io.cpp) into
# PREFIX/lib/lightning2, where the programs find it by name through their run path, relative to
# where they are, and the programs of users of the package (below) through theirs: the installed
# programs and package do not use the build tree.
set(l2_private_libdir ${CMAKE_INSTALL_LIBDIR}/lightning2)
install(TARGETS l2_png_oiio LIBRARY DESTINATION ${l2_private_libdir})
file(RELATIVE_PATH l2_bin_to_libdir /${CMAKE_INSTALL_BINDIR} /${l2_private_libdir})
set_target_properties(${l2_installed_programs} PROPERTIES INSTALL_RPATH "$ORIGIN/${l2_bin_to_libdir}")
target_link_options(l2_picture_files INTERFACE
                    "$<INSTALL_INTERFACE:LINKER:-rpath,$<INSTALL_PREFIX>/${l2_private_libdir}>")

set(l2_share ${CMAKE_INSTALL_DATADIR}/lightning2)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/walls DESTINATION ${l2_share} FILES_MATCHING PATTERN "*.toml")
install(FILES ${CMAKE_SOURCE_DIR}/data/bunny.ply ${CMAKE_SOURCE_DIR}/data/README.md
        DESTINATION ${l2_share}/data)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/tests/golden_images DESTINATION ${l2_share}/tests)
install(FILES ${CMAKE_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The renderer library as a CMake package, for programs of your own drawing built outside this
# tree (examples/README.md):
#
#   find_package(Lightning2 REQUIRED)    # -DCMAKE_PREFIX_PATH=PREFIX
#   target_link_libraries(my_renderer PRIVATE Lightning2::renderer)
#
# PREFIX/lib/cmake/Lightning2 holds the package; PREFIX/lib/lightning2 the static libraries
# Lightning2::renderer (l2_renderer, pipeserver/CMakeLists.txt) links, all the way down, as a
# static library's users link what it links; PREFIX/include/lightning2 the headers the renderer
# API includes. What the project compiles its own code with stays out of the package: the
# warnings and -Werror (Warnings.cmake), the precompiled headers and unity builds (Targets.cmake)
# are all PRIVATE, so the exported targets carry no compile options, and a user's program is
# compiled with the user's flags alone (the test examples_outside_project checks both).
#
# l2_pipeserver_lsan, the LeakSanitizer suppression of OSMesa's never-freed buffers, is left
# out: it matters only under the sanitizers, whose builds this project runs in their build
# trees, and it works only linked as objects (pipeserver/CMakeLists.txt). Installed as a small
# static library it would do nothing: the linker takes a member of an archive only for a symbol
# the program still lacks, and the sanitizer runtime defines these hooks itself (weakly). A
# user's own ASan build of a renderer suppresses the same leak with
# LSAN_OPTIONS=suppressions=FILE, FILE holding "leak:libOSMesa.so" (examples/README.md).
include(CMakePackageConfigHelpers)
set(l2_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/Lightning2)

# The targets `target` links, itself included: the project's libraries in `out`, the imported
# targets (another package's) in `out_imported`. Plain library names (rt, dl) are not targets.
# An imported target made in a part's folder (pkg_check_modules, find_package there) is not
# seen from here: a name with "::" that is not a target here is one.
function(l2_link_closure out out_imported target)
  set(closure)
  set(imported)
  set(todo ${target})
  while(todo)
    list(POP_FRONT todo item)
    if(item MATCHES "^\\$<LINK_ONLY:(.+)>$")
      set(item ${CMAKE_MATCH_1})
    endif()
    if(item IN_LIST closure OR item IN_LIST imported)
      continue()
    endif()
    if(NOT TARGET ${item})
      if(item MATCHES "::")
        list(APPEND imported ${item})
      endif()
      continue()
    endif()
    get_target_property(is_imported ${item} IMPORTED)
    if(is_imported)
      list(APPEND imported ${item})
      continue()
    endif()
    get_target_property(type ${item} TYPE)
    if(NOT type MATCHES "^(STATIC_LIBRARY|INTERFACE_LIBRARY)$")
      message(FATAL_ERROR "Lightning2::renderer links ${item}, a ${type}: the package "
                          "(cmake/Install.cmake) installs static and header-only libraries only")
    endif()
    list(APPEND closure ${item})
    get_target_property(links ${item} INTERFACE_LINK_LIBRARIES)
    if(links)
      list(APPEND todo ${links})
    endif()
  endwhile()
  set(${out} ${closure} PARENT_SCOPE)
  set(${out_imported} ${imported} PARENT_SCOPE)
endfunction()
l2_link_closure(l2_package_targets l2_package_imported l2_renderer)

# How the package's config finds each imported target the libraries link: the same packages
# and pkg-config modules as this build (a target missing here stops the configuration).
set(l2_package_finds
    fmt::fmt "find_dependency(fmt)"
    glm::glm "find_dependency(glm)"
    CLI11::CLI11 "find_dependency(CLI11)"
    Threads::Threads "find_dependency(Threads)"
    nlohmann_json::nlohmann_json "find_dependency(nlohmann_json)"
    MPI::MPI_CXX "find_dependency(MPI COMPONENTS CXX)"
    PkgConfig::EGL "l2_pkg_target(EGL egl)"
    PkgConfig::ASSIMP "l2_pkg_target(ASSIMP assimp)"
    PkgConfig::TOMLPP "l2_pkg_target(TOMLPP tomlplusplus)"
    PkgConfig::LZ4 "l2_pkg_target(LZ4 liblz4)"
    PkgConfig::PNG "l2_pkg_target(PNG libpng)"
    PkgConfig::ZSTD "l2_pkg_target(ZSTD libzstd)")
set(L2_PACKAGE_DEPENDENCIES "")
foreach(dependency ${l2_package_imported})
  list(FIND l2_package_finds ${dependency} at)
  if(at EQUAL -1)
    message(FATAL_ERROR "Lightning2::renderer links ${dependency}: say in cmake/Install.cmake "
                        "(l2_package_finds) how the package's users find it")
  endif()
  math(EXPR at "${at} + 1")
  list(GET l2_package_finds ${at} find)
  string(APPEND L2_PACKAGE_DEPENDENCIES "${find}\n")
endforeach()

install(TARGETS ${l2_package_targets} EXPORT Lightning2Targets
        ARCHIVE DESTINATION ${l2_private_libdir}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lightning2)
install(EXPORT Lightning2Targets NAMESPACE Lightning2:: DESTINATION ${l2_package_dir})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/Lightning2Config.cmake.in
                              ${CMAKE_BINARY_DIR}/Lightning2Config.cmake
                              INSTALL_DESTINATION ${l2_package_dir})
# 0.x: a new minor version may change the API.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/Lightning2ConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/Lightning2Config.cmake
              ${CMAKE_BINARY_DIR}/Lightning2ConfigVersion.cmake
        DESTINATION ${l2_package_dir})

# The headers: renderer.hpp and every header of this tree it includes, transitively, found the
# way the compiler finds them for a user of l2_renderer (InstallHeaders.cmake), so that the
# list cannot drift from the code.
install(CODE "
  set(l2_headers pipeserver/renderer.hpp)
  set(l2_header_roots \"$<TARGET_PROPERTY:l2_renderer,INTERFACE_INCLUDE_DIRECTORIES>\")
  set(l2_header_tree ${CMAKE_SOURCE_DIR})
  set(l2_header_destination ${CMAKE_INSTALL_INCLUDEDIR}/lightning2)
  include(${CMAKE_CURRENT_LIST_DIR}/InstallHeaders.cmake)")
