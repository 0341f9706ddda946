# One place for the warning set, so every target of the project is held to the same bar.
function(l2_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion -Wnon-virtual-dtor)
  if(L2_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
