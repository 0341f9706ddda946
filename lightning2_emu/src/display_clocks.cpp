#include "lightning2_emu/display_clocks.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace l2 {
namespace {

constexpr std::int64_t kMillion = 1000000;

// floor(a / b) and ceil(a / b) for a >= 0, b > 0.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  return a / b;
}
std::int64_t ceil_div(std::int64_t a, std::int64_t b) {
  return (a + b - 1) / b;
}

}  // namespace

DisplayClocks::DisplayClocks(std::vector<int> ppm, std::vector<SwapGroup> groups, bool house_sync)
    : ppm_(std::move(ppm)),
      groups_(std::move(groups)),
      house_sync_(house_sync),
      history_(ppm_.size() * kHistory, -1),
      shown_(ppm_.size(), -1),
      counters_(ppm_.size(), 0),
      mismatched_(groups_.size(), 0) {
  for (std::size_t d = 0; d < ppm_.size(); ++d) {
    if (ppm_[d] < -kMaxDisplayClockPpm || ppm_[d] > kMaxDisplayClockPpm)
      throw std::invalid_argument(
          fmt::format("display {}: clock {} ppm is beyond ±{}", d, ppm_[d], kMaxDisplayClockPpm));
  }
  for (const SwapGroup& g : groups_) {
    for (const int id : g.displays) {
      if (id < 0 || static_cast<std::size_t>(id) >= ppm_.size())
        throw std::invalid_argument(fmt::format(
            "swap group {} names display {}, one of {} displays", g.id, id, ppm_.size()));
    }
  }
}

// Retrace n of a display whose clock runs at rate r = (1e6 + ppm) / 1e6 is at time n / r, so the
// last one at or before s is floor(s·r), in integers to stay exact.
std::int64_t DisplayClocks::last_retrace(std::size_t display, std::int64_t s) const {
  if (house_sync_) return s;
  return floor_div(s * (kMillion + ppm_[display]), kMillion);
}

// Retrace n at time n / r took the frame completed before it: locked(ceil(n / r)).
std::int64_t DisplayClocks::refresh_taken(std::size_t display, std::int64_t retrace) const {
  if (house_sync_) return retrace;
  return ceil_div(retrace * kMillion, kMillion + ppm_[display]);
}

int DisplayClocks::locked_at(std::size_t display, std::int64_t refresh) const {
  return history_[display * kHistory + static_cast<std::size_t>(refresh) % kHistory];
}

void DisplayClocks::refresh(std::span<const int> locked) {
  const auto s = static_cast<std::int64_t>(refreshes_++);
  for (std::size_t d = 0; d < ppm_.size(); ++d) {
    history_[d * kHistory + static_cast<std::size_t>(s) % kHistory] =
        d < locked.size() ? locked[d] : -1;
    counters_[d] = last_retrace(d, s);
    // Within ±kMaxDisplayClockPpm a display's last retrace is less than two periods back, so the
    // refresh it took is s or s - 1: still in the history.
    shown_[d] = locked_at(d, refresh_taken(d, counters_[d]));
  }
  count_mismatches();
}

void DisplayClocks::count_mismatches() {
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    int first = -1;
    for (const int id : groups_[g].displays) {
      const int f = shown_[static_cast<std::size_t>(id)];
      if (f < 0) continue;
      if (first < 0) {
        first = f;
      } else if (f != first) {
        ++mismatched_[g];
        break;
      }
    }
  }
}

}  // namespace l2
