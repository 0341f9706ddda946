#include "bench_args.hpp"

#include "command_line/parse.hpp"

std::optional<int> parse_bench_args(int argc, char** argv, BenchArgs& args) {
  CLI::App app{
      "lightning2_emu_bench: routing throughput of the emulator against memcpy of the same bytes,\n"
      "timed in alternation in the same run, for the WireGL headline case (one 3200x2400 display\n"
      "fed by 12 inputs of 1280x1024, 200x200 tiles) and a 4-display wall of 64x48 tiles, on one\n"
      "worker and on every core; the headline frame rate against the hardware's 90 Hz; the\n"
      "emulator's memory and the peak RSS. Targets: routing/memcpy 0.7 (aim 0.9), 90 frames/s\n"
      "(aim 180); then routing against memcpy over mesh sizes from 4 inputs x 1 display to 64\n"
      "inputs x 24 displays. Exit status 1 when a routed display is wrong, 2 on a usage error."};
  app.add_option("repetitions", args.repetitions,
                 "runs per figure: each figure is the fastest run, each ratio also the median of "
                 "the per-run pairs")
      ->check(CLI::Range(3, 100000))
      ->capture_default_str();
  app.add_flag("--sweep", args.sweep_only,
               "only the mesh-size sweep (4 inputs x 1 display to 64 inputs x 24 displays), with "
               "`repetitions` runs per point; without it the sweep runs last, with a quarter of "
               "them");
  app.add_flag("--small-tiles", args.small_tiles_only,
               "only the 4-display wall of 64x48 tiles (the per-strip cost)");
  app.add_flag("--headline", args.headline_only,
               "only the WireGL headline case (one 3200x2400 display from 12 inputs)");
  app.add_flag("--compositing", args.compositing_only,
               "only the DEPTH compositing cases (sort-last and hybrid)");
  app.add_option("--coverage", args.coverage_percent,
                 "the compositing cases' second coverage: each layer draws a disc of this share "
                 "of the display, its rows sent sparse, timed against full coverage")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  return l2::parse_command_line(app, argc, argv);
}
