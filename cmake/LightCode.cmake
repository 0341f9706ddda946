# Test code and edge code (command-line setup, report formatting) are built once per run of the
# suite and run for seconds, yet they were most of its compile time: GoogleTest, CLI11 and
# nlohmann::json expand to much inline code in every file that uses them, and optimising that
# code (and, in sanitizer builds, instrumenting it) is what costs. Such code is compiled with
# L2_LIGHT_CODE_FLAGS, set per preset (CMakePresets.json: -O0, and no UBSan under ASan). The
# libraries under test keep the build type's flags and every sanitizer.
set(L2_LIGHT_CODE_FLAGS "-O0" CACHE STRING
    "Flags for test code and edge code (appended, so they override the build type's -O)")
separate_arguments(l2_light_code_flags UNIX_COMMAND "${L2_LIGHT_CODE_FLAGS}")

# Marks source files of the calling directory as edge code: not on any hot path.
function(l2_edge_sources)
  set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS "${l2_light_code_flags}"
                                                 SKIP_PRECOMPILE_HEADERS ON)
endfunction()
