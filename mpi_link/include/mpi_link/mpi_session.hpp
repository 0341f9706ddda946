// One process's part in an MPI run of a wall (docs/mpi-design.md): MPI_Init on construction,
// MPI_Finalize on destruction, and who every rank is (process id and host name, gathered on
// the coordinator, so a fault names where a rank ran; its machine's cores and whether its MPI
// busy-polls, so the coordinator can warn of a machine given more ranks than cores).
#pragma once

#include <mpi.h>

#include <array>
#include <atomic>
#include <chrono>
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
  // A rank that dies while the run starts (before its liveness connection) leaves the others in
  // a collective for ever when mpirun keeps the job (orte_enable_recovery): each rank ends
  // after `start_timeout` without a session, rank 0 saying why in one line.
  // `liveness_timeout`: the silence on a liveness connection after which its other end is taken
  // as lost (a host cut off the network closes no connection); the same on every rank.
  MpiSession(std::chrono::milliseconds start_timeout, std::chrono::milliseconds liveness_timeout);
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
  // well), at once, and the coordinator can name the rank before mpirun ends the job. Both ends
  // pulse on it (liveness.hpp): a rank silent for the liveness timeout, its host cut off, is
  // lost too. A thread watches them. `describe(rank)` is the line of a loss that ends the run,
  // empty for one the run survives (a pipeserver under --survive-host-loss, whose mpirun keeps the
  // job): after a loss that ends the run the thread waits briefly for the run to take it up
  // (lost_ranks()), otherwise prints the line itself ("l2wall: ..."), since mpirun may be ending
  // this process already, and watches no more.
  void watch_ranks(std::function<std::string(int rank)> describe);
  void stop_watching();
  // Whether the watch printed `line` (a loss's line, without "l2wall: ") itself.
  bool said(const std::string& line);
  // The ranks found gone so far, in the order found; the run reports them from here on.
  std::vector<int> lost_ranks();
  // Whether `rank` was found gone (the run reports it from here on, if so).
  bool gone(int rank);
  // How a rank found gone was lost, for its line: "is gone (its connection to the coordinator
  // closed: killed or crashed)", "is lost (no word for 3 s: its host's network may be down)"
  // ("stopped, on the coordinator's own host" where no network joins them).
  std::string loss_cause(int rank);
  // The exit code of a rank that ended by its own error and said so (abort_all): it is blamed
  // as a process's exit status is on one machine. nullopt for any other end.
  std::optional<int> exit_code(int rank);

  // Ends every rank of the run (MPI_Abort): for a fault, after its message was printed. Under
  // an mpirun that keeps the job, where MPI_Abort ends only its caller, the coordinator asks
  // mpirun to end the job too. Any other rank first tells the coordinator its exit code
  // (exit_code()): it ends by its own error, not killed.
  // A rank other than 0 that took a stop signal waits for the coordinator's word instead: the
  // run is being stopped, and an abort would cut the coordinator off before its report.
  [[noreturn]] static void abort_all(int code);
  // A rank other than 0 whose failure is the effect of another's fault (a pipeserver that gave
  // up waiting for READY): tells the coordinator its exit code as abort_all does, then leaves
  // the end to the coordinator, which names the cause and ends the job (its word ends this
  // process); only when no word comes within kStopGrace does it abort. Aborting at once would
  // have mpirun end the job before the coordinator could name the cause.
  [[noreturn]] static void end_as_effect(int code);
  // Rank 0, after a run that went on without a lost rank under an mpirun that keeps the job:
  // Open MPI 4.1's mpirun, and the daemon of the lost rank's host, never count that rank as
  // ended and wait for ever once every other has. Every rank's part is done: asks mpirun to end
  // the job, saying so in one line.
  void end_job_after_loss();
  // Rank 0, once a stop signal (Ctrl-C on mpirun: SIGTERM to every rank at once) ended the run
  // and its report is written: tells every other rank, which waited for this word
  // (deferred_stop.hpp) and now ends with status 0, and ends this process with `code` at once:
  // MPI_Finalize would wait for ranks that end without it, and mpirun is ending the job. (This
  // process's status may still be SIGKILL's: mpirun kills the rest once a rank has ended.)
  [[noreturn]] void end_stopped(int code);

 private:
  // Every rank connects to the coordinator's listener (coordinator_address.hpp); a rank
  // that cannot is named by the coordinator in one line, and the run ends before it starts.
  void connect_liveness();
  void accept_liveness(const Fd& listener, MPI_Request& gathered,
                       const std::vector<std::array<char, 240>>& errors);
  void refuse_unreached(const std::vector<std::array<char, 240>>& errors);
  void watch(std::stop_token stop);
  // Rank 0: pulses to every rank until the session ends.
  void pulse(std::stop_token stop);
  // Any rank but 0: pulses to the coordinator, and ends this rank, in one line naming the
  // coordinator's host, when the coordinator is gone without its word of a good end (killed,
  // crashed) or silent for the liveness timeout (its host cut off): MPI_Abort of an mpirun that
  // keeps the job ends only its caller, and a cut-off host's ranks cannot be reached. A
  // coordinator that ends the run on a fault says so first: the rank then ends without a line
  // (its waits on the others would only add effects of the fault named).
  // A rank that took a stop signal (deferred_stop.hpp) ends on the coordinator's word that the
  // run's report is written, or as the signal would have once that word is overdue; and without
  // a line when it loses the coordinator: mpirun is ending the job, the coordinator with it.
  void follow_coordinator(std::stop_token stop);
  [[noreturn]] void lose_coordinator(const std::string& how);
  // Stops watching and tells the other end(s) of the liveness connections of a good end.
  void say_ended();
  // A rank other than 0 that took a stop signal (deferred_stop.hpp). It must not end before
  // the coordinator's word: Open MPI 4.1's mpirun, ending the job, sends SIGKILL to every rank
  // as soon as one has ended, however soon after its SIGTERM, and so cut the coordinator off
  // before its report.
  static bool rank_is_stopping();
  // Waits for the coordinator's word (follow_coordinator ends this process on it), else ends by
  // the signal once it is overdue.
  [[noreturn]] static void await_coordinator_word();
  // abort_all's and end_as_effect's one way: a rank other than 0 says `code` and then leaves the
  // end to the coordinator for `wait` before it aborts.
  [[noreturn]] static void end_after_word(int code, std::chrono::milliseconds wait);
  // Takes in a rank found gone, `cause` as loss_cause says it; true when its loss ends the run.
  bool note_lost(int rank, std::string cause);
  // note_lost of a rank that said it ends by its own error with `code` (-1: the code was cut).
  bool note_failed(int rank, int code);
  // Prints the line of a loss that ends the run, unless the run reported it.
  void report_unclaimed();

  int rank_ = 0;
  int size_ = 0;
  std::vector<RankIdentity> identities_;
  std::chrono::milliseconds liveness_timeout_;
  // Rank 0: by rank, the connection (none for itself); else one. Made before the threads, closed
  // after them.
  std::vector<Fd> liveness_;
  std::function<std::string(int)> describe_;
  std::mutex mutex_;  // guards the three below: the watcher writes them, the run reads them
  std::vector<int> lost_;
  bool claimed_ = false;  // the run took up the losses found so far
  std::string lost_line_;
  std::string printed_;              // the loss's line the watch printed itself, if it did
  std::vector<std::string> causes_;  // by rank: how it was lost, empty if not
  std::vector<std::optional<int>> exit_codes_;  // by rank: the code it ended with, if it said
  std::jthread watcher_;                        // rank 0: watch(), from watch_ranks()
  std::jthread pulse_;                          // rank 0: pulse(); any other: follow_coordinator()
};

// The rank and size mpirun gave this process, read from its environment before MPI_Init
// (OMPI_COMM_WORLD_RANK / _SIZE); nullopt outside mpirun.
struct LaunchedRank {
  int rank = 0;
  int size = 0;
  // mpirun keeps the job when a rank dies (--mca orte_enable_recovery 1 --mca
  // orte_abort_on_non_zero_status 0, which it passes on to every rank's environment).
  bool keeps_job = false;
};
std::optional<LaunchedRank> launched_rank();

}  // namespace l2
