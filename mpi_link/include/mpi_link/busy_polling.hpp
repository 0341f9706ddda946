// Open MPI busy-polls while a rank waits for a message unless it yields the core (its MCA
// parameter mpi_yield_when_idle). It yields by itself where it knows a machine has more ranks
// than slots (mpirun --oversubscribe, slots counted from the cores), but not where a hostfile
// promises more slots than the machine has cores (`localhost slots=8` on 2 cores): then every
// waiting rank spins on a core the working ranks need, and the run is several times slower
// (README, "The wall across machines"). The coordinator says so in one line at the start.
//
// Example:
//
//   MpiSession session;  // every rank's identity: host, cores, yields
//   if (const auto line = busy_polling_warning(session.identities()))
//     std::fprintf(stderr, "l2wall: --mpi: %s\n", line->c_str());
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mpi_link/mpi_session.hpp"

namespace l2 {

// Whether this process's MPI yields while it waits: the value of mpi_yield_when_idle that
// MPI itself holds (MPI_T), or, where that cannot be read, whether mpirun passed
// `--mca mpi_yield_when_idle 1` (the ranks' OMPI_MCA_mpi_yield_when_idle). MPI initialised.
bool mpi_yields_when_idle();

// The machines (by host name) with more ranks than cores where a rank busy-polls, in one line
// naming each with its ranks and cores and the option that helps; nullopt when there are none.
std::optional<std::string> busy_polling_warning(const std::vector<RankIdentity>& ranks);

}  // namespace l2
