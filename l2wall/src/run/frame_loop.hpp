#pragma once

#include <memory>

#include "l2wall/live_show.hpp"
#include "page_steering.hpp"
#include "progress_line.hpp"
#include "run_core.hpp"
#include "run_windows.hpp"
#include "run_writer.hpp"
#include "touch_steering.hpp"
#include "watchdog.hpp"

namespace l2 {

// The parts the frame loop drives at each step, all owned by LiveRun.
struct FrameLoopParts {
  Watchdog& watchdog;
  PageSteering& steering;
  RunWindows& windows;
  TouchSteering& touch;
  RunWriter& writer;
  ProgressLine& progress;
};

// The frame loop of a live run: the lead path's steps until every frame is on the displays, and
// what each swap does: the frames it completed recorded, their latency checked, the other path's
// frame taken (and compared), kept frames saved, fault injection, the displays on screen
// (--show, whose keys it takes), the page told, the progress line. It alone advances the frame
// ledger. It issues the window commands of --window-stdin and --tuio. It may not end processes or
// name a fault's cause: the watchdog names it, LiveRun ends the processes.
class FrameLoop {
 public:
  FrameLoop(RunCore& core, const RunWatch& watch, const FrameLoopParts& parts)
      : core_(core), watch_(watch), parts_(parts) {}

  // --show: opens the displays on screen, before any process starts.
  void open_show();
  // Until --frames frames are on the displays, q under --show, a stop from the page, or a stop
  // signal once a frame is shown (which ends the frames as q does).
  void run_until_stopped();
  // After q, a stop or a stop signal: the frames shown so far are the run, as if --frames had
  // said so; --keep last saves the last of them.
  void cut_at_shown();
  // The --show line of the summary, or empty.
  std::string show_summary() const;

 private:
  void run_frames();
  void on_swap(const PathSwap& swap);
  void record_frame(const PathSwap& swap);
  void check_latency(const FrameRecord& r);
  void take_from_other_paths(int frame);
  void show_last_frame();
  bool keep_showing();
  void take_stdin_windows();
  void take_touch_windows();
  void take_window_command(const std::string& line, const char* from);

  RunCore& core_;
  const RunWatch& watch_;
  FrameLoopParts parts_;
  std::unique_ptr<LiveShow> show_;  // --show: the displays on screen, keys
};

}  // namespace l2
