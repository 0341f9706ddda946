// The `l2wall run` subcommand: its options (the wall, scene and frames, the paths, the processes,
// how the run is watched and steered, fault injection, --mpi), their checks across options, and
// the run on one machine or over MPI ranks; and `l2wall plot`, which draws a run's report. The
// run itself is run_wall() (l2wall/live_run.hpp) and, with --mpi, run_wall_mpi().
#pragma once

namespace CLI {
class App;
}

namespace l2 {

// Adds `run` and `plot` to `app`. Each runs during parsing and ends it with its exit code (a
// CLI::RuntimeError), as `golden` and `view` do.
void add_run_command(CLI::App& app);

}  // namespace l2
