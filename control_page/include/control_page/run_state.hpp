// What the control page shows of a run, as one snapshot: the wall as its file places it, where
// the run is, the current tiles, each pipeserver's recent times and what happened so far. The
// live run fills one a few times a second; `l2wall view` fills one from a run folder. Plain data
// and its JSON (GET /api/state); no I/O.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/orientation.hpp"

namespace l2 {

struct PageDisplay {
  int id = 0;
  int x = 0, y = 0, width = 0, height = 0;  // on the canvas, as it hangs
  int swap_group = 0;
  Orientation orientation;  // how it hangs: its pictures are published turned so
};

struct PageTile {
  int x = 0, y = 0, width = 0, height = 0;  // on the canvas
  int pipeserver = 0;
};

// A session's window as the displays show it (docs/session-file.md): the page draws its outline
// and moves it by dragging.
struct PageWindow {
  int id = 0;
  std::string source;                       // "picture", "mesh", ...
  int x = 0, y = 0, width = 0, height = 0;  // on the canvas
};

// A screen shared from a browser into the run (share_inbox.hpp), as its window's source.
struct PageShare {
  int window = 0;
  std::string name;  // who shares it, as the sharer's page says
  int width = 0, height = 0;
  long received = 0;                // frames decoded and kept
  long shown = 0;                   // of those, taken by the run into a frame
  long dropped = 0;                 // replaced by a newer one before the run took them
  long refused = 0;                 // not a JPEG, damaged, or of another size
  double seconds_since_frame = -1;  // -1: none received yet
};

// One pipeserver's figures of one frame, as its log line says them.
struct PageFrameTimes {
  int frame = 0;
  double render_ms = 0, ready_wait_ms = 0;
  int sync_retries = 0;
};

struct PagePipeserver {
  int index = 0;
  std::string place;                   // "pid 4242", "rank 3 on host-b"
  std::vector<PageFrameTimes> recent;  // oldest first, the last few dozen frames
  std::string back_channel;            // its totals once it ended (the log's "done" line)
  bool lost = false;                   // ended and survived (--survive-host-loss)
  std::string renderer;                // what it renders with, and why (the log's first line)
};

struct PageEvent {
  int frame = 0;  // the frame on the displays when it happened; -1: before the first
  std::string text;
};

struct RunState {
  std::string wall_name;
  int canvas_width = 0, canvas_height = 0;
  std::vector<PageDisplay> displays;
  std::string path;  // "dvi", "vizserver", "both"
  int frames_planned = 0;
  int frame = -1;  // the last frame on every display; -1: none yet
  double fps = 0;
  long latency_frames = -1;  // of the last frame; -1: not measured
  std::string limited_by;    // "limited by ..." of the recent frames, as the summary says it
  bool paused = false;
  bool stoppable = true;  // whether POST /api/stop can end this run (not under --mpi)
  bool live = true;       // false: a finished run served by `l2wall view`
  std::string ended;      // how the run ended ("" while it runs): its summary's first line
  std::string summary;
  std::string balance_mode;                 // "" for a run that does not balance
  std::vector<std::string> balance_modes;   // what POST /api/balance accepts
  std::vector<PageTile> tiles;              // the layout of `frame`
  std::vector<PageWindow> windows;          // a session's windows at `frame`, back to front
  bool windows_movable = false;             // whether POST /api/window moves them in this run
  int share_slots = 0;                      // screens a browser may share at once; 0: none
  std::vector<PageShare> shares;            // the screens shared now
  std::vector<PagePipeserver> pipeservers;  // in pipeserver order
  std::vector<PageEvent> events;            // oldest first, the last few dozen
  std::vector<std::string> pictures;        // other pictures served at /api/picture/NAME
  std::uint64_t pictures_version = 0;       // grows when the display pictures change
};

// The JSON the page reads (docs: control_page/README.md).
std::string to_json(const RunState& state);

}  // namespace l2
