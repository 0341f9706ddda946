# `cmake --install`: the programs into PREFIX/bin; what they find by default beside them
# (command_line/program_paths.hpp) into PREFIX/share/lightning2: the example walls, the bunny of
# the mesh scene and the golden images with their manifest; the documentation into
# PREFIX/share/doc/lightning2.
include(GNUInstallDirs)
install(TARGETS l2wall pipeserver vizserver lightning2_emu tilelayout strip_headers
                sync_backchannel show_wall
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
set(l2_share ${CMAKE_INSTALL_DATADIR}/lightning2)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/walls DESTINATION ${l2_share} FILES_MATCHING PATTERN "*.toml")
install(FILES ${CMAKE_SOURCE_DIR}/data/bunny.ply ${CMAKE_SOURCE_DIR}/data/README.md
        DESTINATION ${l2_share}/data)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/tests/golden_images DESTINATION ${l2_share}/tests)
install(FILES ${CMAKE_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
