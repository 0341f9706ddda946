// `l2wall run --wall WALL --mpi`, in every rank of `mpirun -np N` (docs/mpi-design.md). The rank's
// role comes from rank order: a pipeserver rank becomes the pipeserver program (execv before
// MPI_Init: mpirun's environment carries over, so the pipeserver joins the run as this rank),
// a board column rank routes and holds its displays, rank 0 runs the live run on the MPI
// backends (the coordinator).
#pragma once

#include <optional>
#include <string>

#include "l2wall/live_run.hpp"

namespace l2 {

// What --mpi cannot run with, or nullopt.
Status mpi_options_error(const RunOptions& options);

// Returns the exit code. A fault ends every rank (MPI_Abort) after its message.
int run_wall_mpi(const RunOptions& options);

// Whether this process is rank 0 of the job, the coordinator, which says what is said once for
// the whole run (every rank runs l2wall's checks before MPI_Init); true outside mpirun.
bool coordinator_rank();

}  // namespace l2
