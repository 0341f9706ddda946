# One precompiled header (fmt and the standard library) for the project's own libraries and
# programs; the tests have theirs (Tests.cmake). Parsing these headers was about half the
# compile time of a typical source file. A target may reuse a precompiled header only when its
# flags match, so every target that reuses it also links fmt (FMT_SHARED); edge sources,
# compiled with other flags (LightCode.cmake), parse their headers themselves.
file(WRITE ${CMAKE_BINARY_DIR}/l2_code_pch.cpp "// the precompiled header's own translation unit\n")
add_library(l2_code_pch STATIC ${CMAKE_BINARY_DIR}/l2_code_pch.cpp)
l2_warnings(l2_code_pch)
target_link_libraries(l2_code_pch PUBLIC fmt::fmt)
target_precompile_headers(l2_code_pch PRIVATE ${CMAKE_CURRENT_LIST_DIR}/pch_prelude.hpp
                          <fmt/format.h> <algorithm> <array> <chrono> <cstdint> <cstring>
                          <filesystem> <fstream> <functional> <memory> <optional> <span>
                          <stdexcept> <string> <string_view> <thread> <vector>)

# Gives every library and program defined in the listed folders the shared precompiled header
# (targets with one of their own, the tests, are left as they are).
function(l2_reuse_code_pch)
  foreach(dir ${ARGN})
    get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(target ${targets})
      get_target_property(type ${target} TYPE)
      get_target_property(own ${target} PRECOMPILE_HEADERS)
      get_target_property(reused ${target} PRECOMPILE_HEADERS_REUSE_FROM)
      if(type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|EXECUTABLE)$" AND NOT own AND NOT reused)
        target_precompile_headers(${target} REUSE_FROM l2_code_pch)
        target_link_libraries(${target} PRIVATE fmt::fmt)
        # A library's files are compiled together (up to 8 per unit): each unit otherwise
        # re-instantiates what fmt and the standard library leave pending (0.5 s for an empty
        # file with this header). A library that sets UNITY_BUILD itself keeps its choice; edge
        # sources (own flags) stay separate.
        get_property(unity_chosen TARGET ${target} PROPERTY UNITY_BUILD SET)
        if(type STREQUAL "STATIC_LIBRARY" AND NOT unity_chosen)
          set_target_properties(${target} PROPERTIES UNITY_BUILD ON)
        endif()
      endif()
    endforeach()
  endforeach()
endfunction()
