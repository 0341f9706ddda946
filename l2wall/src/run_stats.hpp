// Where a live run's time went, from its per-frame report: the spread (median, 95th percentile,
// largest) of every pipeserver's render time and of the emulator's route and swap time, and which
// of them limited the frame rate, in the words of the run's summary.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace l2 {

struct Spread {
  double p50 = 0, p95 = 0, max = 0;
};

// Nearest-rank percentiles of `values` (the p-th is the smallest value with at least p % of
// them at or below it); nullopt for none.
std::optional<Spread> spread_of(std::vector<double> values);

// The per-frame times of a run, in milliseconds; route and swap are empty without an emulator.
struct RunTimes {
  std::vector<std::vector<double>> render;  // per pipeserver
  // By pipeserver, those lost mid-run (--survive-host-loss): their few frames are listed, but
  // what limited the run is what the others took.
  std::vector<bool> lost;
  std::vector<double> route, swap;
  double refresh_hz = 0;  // the emulator's refresh rate; 0: as fast as possible or none
};

// The summary's lines: "render p50/p95/max: ...", "route ...", "swap ...", then "limited by
// ...": the largest median of the pipeservers' render times, the route time and the refresh
// period (the swap time waits for the next refresh, so it is not a cause of its own).
std::string spread_lines(const RunTimes& times);

}  // namespace l2
