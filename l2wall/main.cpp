// l2wall: the command that runs a Lightning-2 wall, on one machine or over MPI ranks (--mpi).
// Each subcommand is filed on its own (src/*_command.cpp) and runs while the command line is
// parsed, ending it with its exit code.

#include <optional>

#include "command_line/parse.hpp"
#include "golden_command.hpp"
#include "run_command.hpp"
#include "view_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "l2wall: a Lightning-2 wall. `l2wall run` starts one pipeserver process per\n"
      "input of the wall and emulates the Lightning-2 mesh in this process: the pipeservers'\n"
      "scanned-out frames travel through POSIX shared memory (the DVI links), READY goes back\n"
      "over one pty per pipeserver (the serial back-channels). With --mpi (under mpirun) the\n"
      "same wall runs over MPI ranks on several machines (docs/mpi-design.md)."};
  app.require_subcommand(1);
  l2::add_run_command(app);     // `l2wall run` and `l2wall plot OUT`
  l2::add_golden_command(app);  // `l2wall golden check|update`
  l2::add_view_command(app);    // `l2wall view OUT`
  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;
  return 0;  // every subcommand ends the parse with its status
}
