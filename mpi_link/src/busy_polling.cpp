#include "mpi_link/busy_polling.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <mpi.h>

#include <cstdlib>
#include <cstring>
#include <map>

namespace l2 {
namespace {

// MPI's own value of the control variable, or nullopt where the tool interface cannot read it.
std::optional<bool> read_yield_variable() {
  int provided = 0;
  if (MPI_T_init_thread(MPI_THREAD_SINGLE, &provided) != MPI_SUCCESS) return std::nullopt;
  std::optional<bool> value;
  int index = 0;
  if (MPI_T_cvar_get_index("mpi_yield_when_idle", &index) == MPI_SUCCESS) {
    MPI_T_cvar_handle handle;
    int count = 0;
    if (MPI_T_cvar_handle_alloc(index, nullptr, &handle, &count) == MPI_SUCCESS) {
      // A bool (1 byte) in Open MPI; an int elsewhere: room for either, zeroed.
      alignas(8) unsigned char bytes[16] = {};
      if (count == 1 && MPI_T_cvar_read(handle, bytes) == MPI_SUCCESS) {
        bool any = false;
        for (const unsigned char b : bytes) any = any || b != 0;
        value = any;
      }
      MPI_T_cvar_handle_free(&handle);
    }
  }
  MPI_T_finalize();
  return value;
}

}  // namespace

bool mpi_yields_when_idle() {
  if (const std::optional<bool> value = read_yield_variable()) return *value;
  const char* given = std::getenv("OMPI_MCA_mpi_yield_when_idle");
  return given != nullptr && std::strcmp(given, "0") != 0 && std::strcmp(given, "false") != 0;
}

std::optional<std::string> busy_polling_warning(const std::vector<RankIdentity>& ranks) {
  struct Machine {
    int ranks = 0;
    int cores = 0;
    bool spins = false;  // a rank of it busy-polls
  };
  std::map<std::string, Machine> machines;
  std::vector<std::string> order;  // hosts as the ranks first name them
  for (const RankIdentity& r : ranks) {
    auto [it, added] = machines.try_emplace(r.host);
    if (added) order.push_back(r.host);
    Machine& m = it->second;
    ++m.ranks;
    if (r.cores > 0 && (m.cores == 0 || r.cores < m.cores)) m.cores = r.cores;
    m.spins = m.spins || !r.yields;
  }
  std::vector<std::string> crowded;
  for (const std::string& host : order) {
    const Machine& m = machines[host];
    if (m.spins && m.cores > 0 && m.ranks > m.cores)
      crowded.push_back(fmt::format("{} ranks on {}, which has {} core{}", m.ranks, host, m.cores,
                                    m.cores == 1 ? "" : "s"));
  }
  if (crowded.empty()) return std::nullopt;
  return fmt::format(
      "{}, busy-poll while they wait (Open MPI's mpi_yield_when_idle is off), which can make the "
      "run several times slower: add --mca mpi_yield_when_idle 1 to mpirun",
      fmt::join(crowded, "; "));
}

}  // namespace l2
