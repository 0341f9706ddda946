# A faster linker than GNU ld where the toolchain has one: the suite links every program and test
# of three builds, the larger programs with their debug information. GCC links with gold
# (Debian's binutils has it); clang with lld (Debian package lld), since gold warns for every one
# of the helper symbols clang's AddressSanitizer exports. Without either the default linker is
# used.
include(CheckLinkerFlag)
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  check_linker_flag(CXX "-fuse-ld=lld" L2_HAVE_LLD)
  if(L2_HAVE_LLD)
    add_link_options(-fuse-ld=lld)
  endif()
else()
  check_linker_flag(CXX "-fuse-ld=gold" L2_HAVE_GOLD)
  if(L2_HAVE_GOLD)
    add_link_options(-fuse-ld=gold)
  endif()
endif()
