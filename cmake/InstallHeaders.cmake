# Run by `cmake --install` (Install.cmake): installs the headers `l2_headers` (as a user
# includes them: "pipeserver/renderer.hpp") and every header of this tree they include with
# "...", transitively, into PREFIX/`l2_header_destination`, each by its path under the folder it
# was found in. A header is looked for as the compiler looks for it: beside the header including
# it, then in `l2_header_roots` (the include folders of a user of the library) in order. Those
# found outside `l2_header_tree` (another package's) are not installed; one found nowhere stops
# the installation, as it would stop a user's build.
cmake_policy(VERSION 3.25)  # an install script has no project's policies (include() scopes this)

# Each entry: "<including file>|<its installed path>|<name included>" (the first two empty for
# the headers asked for).
set(l2_todo)
foreach(l2_name ${l2_headers})
  list(APPEND l2_todo "||${l2_name}")
endforeach()
set(l2_installed)
while(l2_todo)
  list(POP_FRONT l2_todo l2_entry)
  string(REGEX MATCH "^([^|]*)\\|([^|]*)\\|(.*)$" l2_entry "${l2_entry}")
  set(l2_from "${CMAKE_MATCH_1}")
  set(l2_from_rel "${CMAKE_MATCH_2}")
  set(l2_name "${CMAKE_MATCH_3}")
  set(l2_file)
  if(l2_from)
    cmake_path(GET l2_from PARENT_PATH l2_dir)
    if(EXISTS "${l2_dir}/${l2_name}")
      cmake_path(GET l2_from_rel PARENT_PATH l2_rel)
      cmake_path(APPEND l2_rel "${l2_name}")
      set(l2_file "${l2_dir}/${l2_name}")
    endif()
  endif()
  if(NOT l2_file)
    foreach(l2_root ${l2_header_roots})
      if(EXISTS "${l2_root}/${l2_name}")
        set(l2_rel "${l2_name}")
        set(l2_file "${l2_root}/${l2_name}")
        break()
      endif()
    endforeach()
  endif()
  if(NOT l2_file)
    message(FATAL_ERROR "${l2_from}: includes \"${l2_name}\", which is in none of the include "
                        "folders of Lightning2::renderer: ${l2_header_roots}")
  endif()
  cmake_path(NORMAL_PATH l2_rel)
  cmake_path(NORMAL_PATH l2_file)
  cmake_path(IS_PREFIX l2_header_tree "${l2_file}" NORMALIZE l2_ours)
  if(NOT l2_ours OR l2_file IN_LIST l2_installed)
    continue()
  endif()
  if(l2_rel MATCHES "^\\.\\./")
    message(FATAL_ERROR "${l2_from}: includes \"${l2_name}\", above its include folder")
  endif()
  list(APPEND l2_installed "${l2_file}")
  cmake_path(GET l2_rel PARENT_PATH l2_rel_dir)
  file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/${l2_header_destination}/${l2_rel_dir}"
       TYPE FILE FILES "${l2_file}")
  file(STRINGS "${l2_file}" l2_lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(l2_line ${l2_lines})
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" l2_included "${l2_line}")
    list(APPEND l2_todo "${l2_file}|${l2_rel}|${l2_included}")
  endforeach()
endwhile()
