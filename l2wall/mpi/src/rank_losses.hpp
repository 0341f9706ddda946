// Which ranks of an MPI run are gone, and what that means for the DVI path: a pipeserver's rank
// the run survives (--survive-host-loss: the columns are told at once, and it ends as a
// pipeserver, PipeserverSet::poll_ended); a pipeserver's rank that gave up waiting (its exit
// code says so, live_exit.hpp), an effect left to the run's watchdog, which names the cause as
// on one machine; or any other rank, which ends the run with a line naming it. The session's
// watcher thread finds a loss; this takes it up on the run's thread.
//
// Owns: the session's watch, the pipeservers lost and survived, the rank that ends the run. It
// may not decide anything about frames.
#pragma once

#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "mpi_link/mpi_session.hpp"
#include "mpi_link/rank_map.hpp"

namespace l2 {

class RankLosses {
 public:
  RankLosses(const RankMap& map, MpiSession& session, bool survive);
  ~RankLosses() { session_.stop_watching(); }
  RankLosses(const RankLosses&) = delete;
  RankLosses& operator=(const RankLosses&) = delete;

  // Takes up the ranks lost since last asked: tells every column of a pipeserver survived (once,
  // mpi_wire::kLost). The rank that ends the run, if one is gone.
  std::optional<int> poll();
  std::optional<int> ending() const { return ending_; }
  // Pipeservers whose rank is gone, survived: nothing more comes from them.
  const std::vector<int>& survived() const { return survived_; }
  // "board column 0 (rank 1 on render-a, pid 4242) is gone (...) while the displays wait for
  // frame 8; the displays keep frame 7"; from any thread.
  std::string message(int rank) const;
  // The frame the displays keep, for the messages.
  void showing(int frame) { shown_ = frame; }
  int shown() const { return shown_; }
  std::string displays_showing() const;
  // The fault is named: later losses are its effects.
  void stop_watching() { session_.stop_watching(); }

 private:
  bool survives(int rank) const;
  bool an_effect(int rank) const;

  const RankMap& map_;
  MpiSession& session_;
  bool survive_;
  std::vector<int> survived_;
  std::optional<int> ending_;
  std::atomic<int> shown_{-1};  // read by the session's watcher thread too
};

}  // namespace l2
