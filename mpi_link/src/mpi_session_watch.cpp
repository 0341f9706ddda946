// MpiSession's liveness threads (mpi_session.hpp): the coordinator's watch of every rank, its
// pulse, and every other rank's watch of the coordinator, on the connections made at its start.
#include <fmt/format.h>
#include <poll.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "deferred_stop.hpp"
#include "mpi_link/liveness.hpp"
#include "mpi_link/mpi_session.hpp"

namespace l2 {
namespace {

// How often a watching thread wakes: to pulse, to see a silence out, to stop.
constexpr int kWakeMs = 20;

}  // namespace

void MpiSession::pulse(std::stop_token stop) {
  while (!stop.stop_requested()) {
    for (const Fd& fd : liveness_)
      if (fd) send_liveness(fd.get(), kLivenessPulse);
    std::this_thread::sleep_for(kPulseEvery);
  }
}

void MpiSession::follow_coordinator(std::stop_token stop) {
  const int fd = liveness_.front().get();
  Silence silence(liveness_timeout_, Silence::Clock::now());
  auto next_pulse = Silence::Clock::now();
  std::optional<Silence::Clock::time_point> signalled;  // when a stop signal was seen
  while (!stop.stop_requested()) {
    const auto now = Silence::Clock::now();
    if (stop_signal_received() && !signalled) signalled = now;
    if (signalled && now - *signalled > kStopGrace) end_by_stop_signal();  // never told
    if (now >= next_pulse) {
      send_liveness(fd, kLivenessPulse);
      next_pulse = now + kPulseEvery;
    }
    pollfd p{fd, POLLIN, 0};
    const Heard h = poll(&p, 1, kWakeMs) > 0 ? read_liveness(fd) : Heard::nothing;
    if (h == Heard::ended) return;
    if (h == Heard::aborting) std::_Exit(1);  // the coordinator named the fault
    if (h == Heard::stopped) std::_Exit(0);   // a stop signal's: the report is written
    if (h == Heard::closed) lose_coordinator("its connection closed (killed or crashed)");
    if (h == Heard::pulse) silence.heard(Silence::Clock::now());
    if (silence.too_long(Silence::Clock::now()))
      lose_coordinator(no_word_for(liveness_timeout_) +
                       " (the network between the hosts may be down)");
  }
}

void MpiSession::lose_coordinator(const std::string& how) {
  // Signalled, this rank is being ended with the job (mpirun's SIGTERM to every rank, after a
  // fault it or the coordinator named, or Ctrl-C): the coordinator's end is part of that, and
  // a line of this rank's would name an effect as a second fault.
  if (stop_signal_received()) end_by_stop_signal();
  std::fprintf(stderr,
               "l2wall: rank %d on %s: lost the coordinator (rank 0 on %s): %s; this rank ends\n",
               rank_, identities_[static_cast<std::size_t>(rank_)].host.c_str(),
               identities_.front().host.c_str(), how.c_str());
  std::fflush(stderr);
  std::_Exit(1);
}

void MpiSession::watch_ranks(std::function<std::string(int)> describe) {
  describe_ = std::move(describe);
  watcher_ = std::jthread([this](std::stop_token stop) { watch(stop); });
}

void MpiSession::stop_watching() {
  if (!watcher_.joinable()) return;
  watcher_.request_stop();
  watcher_.join();
  report_unclaimed();
}

void MpiSession::report_unclaimed() {
  const std::lock_guard lock(mutex_);
  if (lost_line_.empty() || claimed_) return;
  claimed_ = true;
  printed_ = lost_line_;
  std::fprintf(stderr, "l2wall: %s\n", lost_line_.c_str());
}

bool MpiSession::said(const std::string& line) {
  const std::lock_guard lock(mutex_);
  return !printed_.empty() && printed_ == line;
}

bool MpiSession::note_lost(int rank, std::string cause) {
  {
    const std::lock_guard lock(mutex_);
    causes_.resize(static_cast<std::size_t>(size_));
    causes_[static_cast<std::size_t>(rank)] = std::move(cause);
  }
  const std::string line = describe_(rank);
  const std::lock_guard lock(mutex_);
  lost_.push_back(rank);
  if (line.empty()) return false;
  lost_line_ = line;
  claimed_ = false;  // this loss is still to be taken up
  return true;
}

bool MpiSession::note_failed(int rank, int code) {
  {
    const std::lock_guard lock(mutex_);
    exit_codes_.resize(static_cast<std::size_t>(size_));
    if (code >= 0) exit_codes_[static_cast<std::size_t>(rank)] = code;
  }
  // As ExitStatus::describe says a child's end on one machine.
  return note_lost(rank, code >= 0 ? fmt::format("exited with code {}", code)
                                   : std::string("ended by its own error (its exit code was cut)"));
}

std::optional<int> MpiSession::exit_code(int rank) {
  const std::lock_guard lock(mutex_);
  const auto r = static_cast<std::size_t>(rank);
  return r < exit_codes_.size() ? exit_codes_[r] : std::nullopt;
}

void MpiSession::watch(std::stop_token stop) {
  const auto start = Silence::Clock::now();
  std::vector<Silence> silences(liveness_.size(), Silence(liveness_timeout_, start));
  std::vector<bool> watched(liveness_.size());
  for (std::size_t r = 0; r < liveness_.size(); ++r) watched[r] = static_cast<bool>(liveness_[r]);
  // A rank on the coordinator's own network stack has no network between them to go down.
  const auto silent = [this](std::size_t r) {
    return fmt::format("is lost ({}: {})", no_word_for(liveness_timeout_),
                       beside(static_cast<int>(r)) ? "stopped, on the coordinator's own host"
                                                   : "its host's network may be down");
  };
  bool fatal = false;
  while (!stop.stop_requested() && !fatal) {
    std::vector<pollfd> fds;
    std::vector<std::size_t> ranks;  // by entry of fds
    for (std::size_t r = 0; r < liveness_.size(); ++r) {
      if (!watched[r]) continue;
      fds.push_back({liveness_[r].get(), POLLIN, 0});
      ranks.push_back(r);
    }
    if (fds.empty()) return;
    poll(fds.data(), fds.size(), kWakeMs);
    const auto now = Silence::Clock::now();
    for (std::size_t i = 0; i < fds.size() && !fatal; ++i) {
      const std::size_t r = ranks[i];
      int code = -1;
      const Heard h = fds[i].revents ? read_liveness(fds[i].fd, &code) : Heard::nothing;
      if (h == Heard::pulse || h == Heard::aborting) silences[r].heard(now);
      if (h == Heard::ended || h == Heard::closed || h == Heard::failed) watched[r] = false;
      if (h == Heard::failed)
        fatal = note_failed(static_cast<int>(r), code);
      else if (h == Heard::closed)
        fatal = note_lost(static_cast<int>(r),
                          "is gone (its connection to the coordinator closed: killed or crashed)");
      else if (watched[r] && silences[r].too_long(now)) {
        watched[r] = false;
        fatal = note_lost(static_cast<int>(r), silent(r));
      }
    }
  }
  if (!fatal) return;
  // The run takes the loss up within milliseconds when it can; if it does not, this process
  // may be ending already (mpirun's SIGTERM): the line must be out first.
  for (int i = 0; i < 30 && !stop.stop_requested(); ++i) {
    {
      const std::lock_guard lock(mutex_);
      if (claimed_) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  report_unclaimed();
}

std::vector<int> MpiSession::lost_ranks() {
  const std::lock_guard lock(mutex_);
  claimed_ = true;
  return lost_;
}

bool MpiSession::gone(int rank) {
  const std::lock_guard lock(mutex_);
  if (std::find(lost_.begin(), lost_.end(), rank) == lost_.end()) return false;
  claimed_ = true;
  return true;
}

std::string MpiSession::loss_cause(int rank) {
  const std::lock_guard lock(mutex_);
  const auto r = static_cast<std::size_t>(rank);
  return r < causes_.size() ? causes_[r] : std::string();
}

}  // namespace l2
