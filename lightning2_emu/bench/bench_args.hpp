// The emulator benchmark's command line, parsed in a file of its own, apart from bench.cpp,
// whose baselines are measured.
#pragma once

#include <optional>

struct BenchArgs {
  int repetitions = 41;
  bool sweep_only = false;        // --sweep: only the mesh-size sweep
  bool small_tiles_only = false;  // --small-tiles: only the wall of 64x48 tiles
  bool compositing_only = false;  // --compositing: only the DEPTH compositing cases
  bool headline_only = false;     // --headline: only the WireGL headline case
  int coverage_percent = 10;      // --coverage: the compositing cases' sparse coverage
};

// Parses the command line into `args`. Returns the exit status to end with at once (0 after
// --help, 2 on a usage error, the error on stderr), or nullopt to run the benchmark.
std::optional<int> parse_bench_args(int argc, char** argv, BenchArgs& args);
