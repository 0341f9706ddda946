// What a live run records per frame, and the report it writes at the end, also when a fault ended
// it (of the frames before the fault): report.csv (one row per frame: refreshes, latency, route
// and swap time, per pipeserver render time, READY wait, SYNC? retries) and summary.txt (frames
// per second, measured latency, the spread of render, route and swap time and what limited the
// run, back-channel counts).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "l2wall/live_run.hpp"
#include "l2wall/run_time.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

struct FrameRecord {
  std::uint64_t in_refresh = 0;    // refresh at which its last input was taken in
  std::uint64_t swap_refresh = 0;  // refresh at which it reached every display
  RunClock::time_point in_time{}, swap_time{};
  double route_ms = 0;    // emulator time of the refreshes that routed this frame
  double writing_ms = 0;  // picture writing of the run up to this frame's swap
  double paused_ms = 0;   // --show pauses of the run up to this frame's swap
  bool shown = false;
};

struct RunTotals {
  std::uint64_t refreshes = 0;
  std::uint64_t noise_bytes = 0, dropped_readies = 0;
  std::uint64_t compared_displays = 0;
  std::uint64_t frames_predicted = 0, predictions_missed = 0;  // the emulator's (DVI path)
  // Said by the lead path (DisplayPath::add_totals): whether it refreshes (so measures the
  // one-frame latency and route times; false on the vizserver path alone), how it paces the run,
  // and the lines the paths add to the summary (what they proved, what crossed the network).
  bool latency_measured = true;
  std::string pace;
  std::string path_lines;
  // Files the paths add to OUT beside report.csv (name, text): the DVI path's frame-lock.csv.
  std::vector<std::pair<std::string, std::string>> path_files;
  RunClock::time_point start{};  // the clock starts once every pipeserver delivered a first frame
  std::vector<bool> lost;        // by pipeserver: lost mid-run (--survive-host-loss)
};

// The texts of OUT/report.csv and OUT/summary.txt (the run writes them, and says what OUT holds
// when it cannot).
struct RunReportTexts {
  std::string csv, summary;
};

// The report from the records and the pipeservers' reports (`pipeserver_logs`:
// pipeserver-<i>.log, in pipeserver order). `extra` lines go into the summary before its last
// line. `fault`: the one-line reason of the fault that ended the run at frame records.size()
// (the summary's first line says so), or empty for a run that ended as it should.
RunReportTexts run_report(const RunOptions& o, const Wall& wall,
                          const std::vector<std::string>& pipeserver_logs,
                          const std::vector<FrameRecord>& records, const RunTotals& totals,
                          const std::string& extra, const std::string& fault);

}  // namespace l2
