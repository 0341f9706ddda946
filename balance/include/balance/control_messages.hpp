// The balancing control channel's messages (a pipeserver and the run's coordinator): after each
// frame a pipeserver sends its tiles' render times; before the next, the coordinator sends
// every pipeserver that frame's tiling, the same to all, so all switch together. One text line
// each, whatever moves them (control_channel.hpp).
//
//   TIMES <frame> <pipeserver> <n> <seconds>... [BATCHES <m> (<x> <y> <w> <h> <triangles>)...]
//                                                    n = the pipeserver's packed tiles;
//                                                    BATCHES: the scene's batch footprints
//   LAYOUT <frame> <n> (<x> <y> <w> <h> <pipeserver>)... [GONE <m> <pipeserver>...]
//                                                    n = logical tiles, in tiling order;
//                                                    GONE: pipeservers that died (no tiles)
//
// A session run's windows travel the same way, on a channel of their own (docs/session-file.md):
//
//   WANT <frame> <pipeserver>                          before its READY wait: that frame's windows
//   WINDOWS <frame> <n> (<id> <x> <y> <w> <h>)...      n = windows shown, back to front
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "tilelayout/batch_footprint.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

struct TimesMessage {
  int frame = 0, pipeserver = 0;
  std::vector<double> seconds;  // by packed tile, as the pipeserver's plan orders them
  Footprints footprints;        // the frame's batches (FrameTimes::footprints), triangles whole
};

struct LayoutMessage {
  int frame = 0;
  std::vector<Rect> tiles;       // the logical tiles on the canvas
  std::vector<int> pipeservers;  // the pipeserver of each
  std::vector<int> gone;         // pipeservers that take no part any more (ascending): a dead host
};

// A line that is not a message, or one whose numbers are out of range: what() is one line
// quoting at most the start of the line.
class ControlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// More tiles than a wall can have (every tile is at least one canvas pixel of a 4095-square
// display, but a line this long is already a wrong peer): refused before anything is kept.
inline constexpr int kMaxControlTiles = 65536;
// The most batch footprints a TIMES line carries; a scene of more sends none (its tiles are
// then priced by their pixels), which keeps every line far under kMaxControlLine.
inline constexpr int kMaxControlBatches = 65536;

struct WantMessage {
  int frame = 0, pipeserver = 0;
};

// Where a window of the session is; a window the message does not list is closed.
struct WindowPlace {
  int id = 0;
  Rect on_canvas;
  friend bool operator==(const WindowPlace&, const WindowPlace&) = default;
};

struct WindowsMessage {
  int frame = 0;
  std::vector<WindowPlace> windows;  // back to front
};

// A session's bounds (tilelayout/session_file.hpp: kMaxWindows, kMaxWindowId, kMaxWindowSide,
// kWindowReach), checked again on a line from the channel.
inline constexpr int kMaxControlWindows = 32;
inline constexpr int kMaxControlWindowId = 9999;
inline constexpr int kMaxControlWindowSide = 16384;
inline constexpr int kControlWindowReach = 16384;

std::string encode(const TimesMessage& m);
std::string encode(const LayoutMessage& m);
TimesMessage decode_times(std::string_view line);
LayoutMessage decode_layout(std::string_view line);
std::string encode(const WantMessage& m);
std::string encode(const WindowsMessage& m);
WantMessage decode_want(std::string_view line);
WindowsMessage decode_windows(std::string_view line);

// What the coordinator sends every pipeserver: `layout` as frame `frame`'s tiling. Its
// pipeservers without a tile are gone (the planner gives every other one a tile).
LayoutMessage layout_message(int frame, const TileLayout& layout);
// The layout a pipeserver plans from the message: `wall` with the message's tiles as a list
// tiling, its pipeservers as the assignment and its gone ones taking no part, through the
// planner (its checks and its LayoutError), so every pipeserver packs the same plan as the
// coordinator.
TileLayout plan_from_message(const Wall& wall, const LayoutMessage& m);

}  // namespace l2
