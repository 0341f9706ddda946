# Links with gold where the toolchain has it (Debian's binutils does): it links the larger
# programs with their debug information several times faster than GNU ld, and the suite links
# every program and test of three builds. Without gold the default linker is used. Not for the fuzz build: gold warns for every one of clang's
# ASan helper symbols, and that build links five small programs.
include(CheckLinkerFlag)
check_linker_flag(CXX "-fuse-ld=gold" L2_HAVE_GOLD)
if(L2_HAVE_GOLD AND NOT L2_FUZZ)
  add_link_options(-fuse-ld=gold)
endif()
