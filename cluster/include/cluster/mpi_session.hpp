// One process's part in an MPI run of a wall (docs/mpi-design.md): MPI_Init on construction,
// MPI_Finalize on destruction, and who every rank is (process id and host name, gathered on
// the coordinator, so a fault names where a rank ran; its machine's cores and whether its MPI
// busy-polls, so the coordinator can warn of a machine given more ranks than cores).
#pragma once

#include <mpi.h>

#include <array>
#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "base/fd.hpp"

namespace l2 {

struct RankIdentity {
  int pid = 0;
  std::string host;
  std::string stack;   // its network stack (coordinator_address.hpp): equal on one machine
  int cores = 0;       // its machine's (std::thread::hardware_concurrency; 0: not known)
  bool yields = true;  // its MPI yields the core while it waits (busy_polling.hpp)
};

class MpiSession {
 public:
  // Errors come back as return codes (MPI_ERRORS_RETURN), not as an abort inside MPI, so a
  // rank that lost a peer can say which one. Collective: every rank constructs one.
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // Every rank's identity, by rank.
  const std::vector<RankIdentity>& identities() const { return identities_; }
  // Whether `rank` runs on this rank's machine (the same network stack): what goes there need
  // not fit a network.
  bool beside(int rank) const {
    return identities_[static_cast<std::size_t>(rank)].stack ==
           identities_[static_cast<std::size_t>(rank_)].stack;
  }

  // On rank 0, every rank holds a TCP connection to it for its whole life, beside MPI: when a
  // rank's process is gone its connection closes (without the word a rank sends as it ends
  // well), at once, and the coordinator can name the rank before mpirun ends the job. A thread
  // watches them: after a loss it waits briefly for the run to take it up (lost_rank()), and
  // otherwise prints `describe(rank)` itself ("l2wall: ..."), since mpirun may be ending this
  // process already.
  void watch_ranks(std::function<std::string(int rank)> describe);
  void stop_watching();
  // The rank found gone, or nullopt; the run reports it from here on.
  std::optional<int> lost_rank();

  // Ends every rank of the run (MPI_Abort): for a fault, after its message was printed.
  [[noreturn]] static void abort_all(int code);

 private:
  // Every rank connects to the coordinator's listener (coordinator_address.hpp); a rank
  // that cannot is named by the coordinator in one line, and the run ends before it starts.
  void connect_liveness();
  void accept_liveness(const Fd& listener, MPI_Request& gathered,
                       const std::vector<std::array<char, 240>>& errors);
  void refuse_unreached(const std::vector<std::array<char, 240>>& errors);
  void watch(std::stop_token stop);
  // Prints the line of a rank found gone, unless the run reported it.
  void report_unclaimed();

  int rank_ = 0;
  int size_ = 0;
  std::vector<RankIdentity> identities_;
  std::vector<Fd> liveness_;  // rank 0: by rank, the connection (none for itself); else one
  std::function<std::string(int)> describe_;
  std::atomic<int> lost_{-1};
  std::atomic<bool> claimed_{false};
  std::mutex line_mutex_;
  std::string lost_line_;
  std::jthread watcher_;
};

// The rank and size mpirun gave this process, read from its environment before MPI_Init
// (OMPI_COMM_WORLD_RANK / _SIZE); nullopt outside mpirun.
struct LaunchedRank {
  int rank = 0;
  int size = 0;
};
std::optional<LaunchedRank> launched_rank();

}  // namespace l2
