#include "rank_losses.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "mpi_link/mpi_wire.hpp"
#include "pipeserver/live_exit.hpp"

namespace l2 {

RankLosses::RankLosses(const RankMap& map, MpiSession& session, bool survive)
    : map_(map), session_(session), survive_(survive) {
  session_.watch_ranks([this](int rank) {
    return survives(rank) || an_effect(rank) ? std::string() : message(rank);
  });
}

bool RankLosses::an_effect(int rank) const {
  const std::optional<int> code = session_.exit_code(rank);
  return map_.pipeserver_of(rank).has_value() && code && gave_up_waiting(*code);
}

bool RankLosses::survives(int rank) const {
  return survive_ && map_.pipeserver_of(rank).has_value();
}

std::string RankLosses::message(int rank) const {
  const auto& who = session_.identities()[static_cast<std::size_t>(rank)];
  return fmt::format("{} (rank {} on {}, pid {}) {} while the displays wait for frame {}; {}",
                     map_.role(rank), rank, who.host, who.pid, session_.loss_cause(rank),
                     shown_ + 1, displays_showing());
}

std::string RankLosses::displays_showing() const {
  const int shown = shown_;
  if (shown < 0) return "no frame reached the displays";
  return fmt::format("the displays keep frame {}", shown);
}

std::optional<int> RankLosses::poll() {
  for (const int rank : session_.lost_ranks()) {
    if (ending_) break;
    if (an_effect(rank)) continue;  // the run's watchdog names the cause (RemotePipeserver)
    if (!survives(rank)) {
      ending_ = rank;
      continue;
    }
    const int pipeserver = *map_.pipeserver_of(rank);
    if (std::find(survived_.begin(), survived_.end(), pipeserver) != survived_.end()) continue;
    survived_.push_back(pipeserver);
    // At once, not at the next tick: a column may be waiting for a frame the pipeserver died
    // sending, and the coordinator for that column's answer.
    for (int c = 0; c < map_.columns; ++c)
      mpi_wire::send({pipeserver}, map_.column_rank(c), mpi_wire::kLost);
  }
  return ending_;
}

}  // namespace l2
