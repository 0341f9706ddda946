# Links with gold where the toolchain has it (Debian's binutils does): GNU ld took about 3 s to
# link one of the larger programs with its debug information, gold 0.6 s; the release build
# links 43 programs and tests, and the suite links two sanitizer builds besides. Without gold
# the default linker is used. Not for the fuzz build: gold warns for every one of clang's
# ASan helper symbols, and that build links five small programs.
include(CheckLinkerFlag)
check_linker_flag(CXX "-fuse-ld=gold" L2_HAVE_GOLD)
if(L2_HAVE_GOLD AND NOT L2_FUZZ)
  add_link_options(-fuse-ld=gold)
endif()
