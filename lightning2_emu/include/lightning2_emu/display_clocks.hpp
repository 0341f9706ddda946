// Frame lock, proven rather than assumed: each display's own refresh clock in virtual time, and
// the frame it shows at each house refresh when that clock runs free or is locked to the house
// sync.
//
// Time is counted in house refreshes (the emulator's refresh clock, the master): house refresh s
// is at time s. Display d retraces at n / (1 + ppm_d·1e-6) for n = 0, 1, ..., all displays
// retracing together at time 0; with house sync every display retraces at the house refreshes.
// At each retrace a display takes the newest frame its swap group completed before that instant;
// the emulator's in-lock swap (what the columns' displays hold at house refresh s, "locked(s)")
// is the newest frame completed before time s. So a display whose last retrace is at time L
// shows locked(ceil(L)) at house refresh s: the frame-lock card reads every display at the house
// pulse. A display slower than the house clock now and then has no retrace between two pulses
// and shows the frame before for that refresh; a faster one gains a retrace at the same rate
// (its frame counter runs ahead) but is never caught behind at a pulse.
//
// Owns: each display's clock and frame counter, the few locked frames a lagging display can
// still show, and the per-group count of refreshes whose displays showed different frames. It
// does no I/O and reads no real clock, so counts are exact and the same on any machine.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lightning2_emu/swap_group.hpp"

namespace l2 {

// A clock faster or slower than this is another refresh rate, not a drifting one; within it a
// display retraces at least once in every two house periods.
inline constexpr int kMaxDisplayClockPpm = 500000;

class DisplayClocks {
 public:
  // `ppm`: by display id, how far each display's clock runs from the house rate. `groups`: the
  // swap-lock groups (display ids). `house_sync`: every retrace locked to the house clock, the
  // ppm notwithstanding. Throws std::invalid_argument for a ppm beyond ±kMaxDisplayClockPpm or a
  // group naming a display `ppm` lacks.
  DisplayClocks(std::vector<int> ppm, std::vector<SwapGroup> groups, bool house_sync);

  // House refresh number refreshes() (0, 1, ...): `locked` by display id, the frame each display
  // holds as the emulator swapped it in lock (-1: none yet; missing entries are -1).
  void refresh(std::span<const int> locked);

  std::uint64_t refreshes() const { return refreshes_; }
  // After refresh(), by display id: the frame it shows by its own clock (-1: none yet).
  const std::vector<int>& shown() const { return shown_; }
  // After refresh(), by display id: its frame counter, the retraces since refresh 0.
  const std::vector<std::int64_t>& counters() const { return counters_; }
  // By group (the constructor's order): refreshes in which two of its displays that show a frame
  // showed different ones.
  const std::vector<std::uint64_t>& mismatched() const { return mismatched_; }
  const std::vector<SwapGroup>& groups() const { return groups_; }
  bool house_sync() const { return house_sync_; }
  const std::vector<int>& ppm() const { return ppm_; }

 private:
  // The last retrace of `display` at or before house refresh `s`, as a retrace number, and the
  // house refresh whose locked frame it took.
  std::int64_t last_retrace(std::size_t display, std::int64_t s) const;
  std::int64_t refresh_taken(std::size_t display, std::int64_t retrace) const;
  int locked_at(std::size_t display, std::int64_t refresh) const;
  void count_mismatches();

  std::vector<int> ppm_;
  std::vector<SwapGroup> groups_;
  bool house_sync_;
  std::uint64_t refreshes_ = 0;
  // By display: its locked frames of the last kHistory refreshes, refresh s at s % kHistory.
  static constexpr std::size_t kHistory = 3;
  std::vector<int> history_;
  std::vector<int> shown_;
  std::vector<std::int64_t> counters_;
  std::vector<std::uint64_t> mismatched_;
};

}  // namespace l2
