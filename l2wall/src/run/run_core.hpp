#pragma once

#include <memory>
#include <string>
#include <vector>

#include "l2wall/display_path.hpp"
#include "l2wall/live_balance.hpp"
#include "l2wall/pipeserver_set.hpp"
#include "l2wall/run_options.hpp"
#include "l2wall/run_report.hpp"
#include "l2wall/run_time.hpp"
#include "live_page.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

// Where the frames are: what reached the displays, when, and what of the run's time was not
// the pipeservers'. The frame loop advances it; the other parts read it, and note the time they
// held the run (a pause, writing pictures).
struct FrameLedger {
  std::vector<FrameRecord> records;  // one per frame of --frames
  RunTotals totals;
  int shown = 0;                     // frames 0 .. shown-1 have reached every display (checked)
  RunClock::time_point last_swap{};  // the stall clock runs from here
  double paused_ms = 0;              // spent paused (--show keys, the page): not fps, no stall
  double writing_ms = 0;             // spent writing saved pictures during the run
  bool latency_ok = true;
  bool pipeservers_started = false;
  bool links_open = false;  // every pipeserver delivered its first frame: the clock runs
  int stopped = 0;          // the stop signal that ended the frames, or 0
};

// What every part of a live run works on: the options, the wall and its plan, the display paths,
// the pipeservers, the balance coordinator, the control page and where the frames are. LiveRun
// owns it and makes it; each part's class comment says which of it the part may change.
struct RunCore {
  // Loads the wall of `o` (the built-in default without one) and plans it; throws what the
  // wall file or the planner refuses, as --keep's parse does.
  explicit RunCore(const RunOptions& o);

  RunOptions options;
  SavedFrames saved;  // --keep
  Wall wall;
  TileLayout layout;
  std::unique_ptr<LivePage> page;                   // --http: the control page, its events
  std::vector<std::unique_ptr<DisplayPath>> paths;  // the lead first (--path)
  std::unique_ptr<LiveBalance> balance;             // a balanced run's coordinator
  // After paths: destroyed first, so pipeservers end before the compositing server.
  PipeserverSet pipeservers;
  FrameLedger frames;

  // The lead path, whose swaps are the run's frames.
  DisplayPath& lead() { return *paths.front(); }
  // The lead's pictures are named display-<i>.png, the other path's display-<i>-<label>.png.
  std::string picture_suffix(std::size_t path) const {
    return path == 0 ? std::string() : "-" + paths[path]->label();
  }
};

}  // namespace l2
