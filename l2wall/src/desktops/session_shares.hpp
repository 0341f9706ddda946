// A session's shared screens on the coordinator (control_page/README.md, docs/session-file.md
// `shares`): a fixed number of slots, each a window id after the file's windows and a desktop
// the pipeservers hold (scene_session.cpp makes the same slots from the same file). A share
// opened fills a free slot with a desktop of its frames' size, fed by its source (a browser
// through the control page: share_source); closing it frees the slot. Every frame, each slot
// answers a pipeserver's WANT with its DESKTOP and RECT lines, as a session's vnc desktops do
// (session_desktops.hpp), after them.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "balance/control_messages.hpp"
#include "base/result.hpp"
#include "desktop_frames.hpp"
#include "desktop_source.hpp"
#include "tilelayout/session_file.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// Where a share's window goes on a canvas of canvas_w x canvas_h: at most half the canvas each
// way and no larger than the share, keeping its aspect, centred at (cx, cy), or at the canvas's
// centre for cx or cy < 0. Pure.
Rect share_place(int canvas_w, int canvas_h, int share_w, int share_h, int cx, int cy);

class SessionShares {
 public:
  SessionShares(const Session& session, const TileLayout& layout);

  int slots() const { return static_cast<int>(slots_.size()); }
  // A free slot's window id, or why none in one line (the session takes no shares, or every
  // slot is in use).
  Result<int> free_window() const;
  // Fills `window`'s slot (free_window's) with `source`, its desktop in the pipeservers' frames
  // from frame `from` on (the first frame whose windows are still to be decided).
  void open(int window, std::unique_ptr<DesktopSource> source, const std::string& name, int from);
  // The share in `window` ended (its window closed): the slot is free. False: no share there.
  bool close(int window);
  // Whether `window` is a share slot's, open or not.
  bool is_share(int window) const;

  // Takes in every open share's frames, waiting for none. Throws DesktopError in one line.
  void take_updates();
  // Every slot's DESKTOP and RECT lines for `pipeserver`'s frame `frame`, in which `shown` are
  // the windows (back to front).
  std::vector<std::string> answer(int pipeserver, int frame, const std::vector<WindowPlace>& shown);
  // "shares: window 5 shared by browser (1280x720) from frame 12", a line a share opened.
  std::string summary() const;

 private:
  // A slot's desktop from frame `from` on; before it, the one before (the pipeservers ask for
  // frames in order, up to a frame apart, so both may be asked for at once).
  struct Era {
    int from = 0;
    std::unique_ptr<DesktopSource> source;  // none: the slot was free
    std::unique_ptr<DesktopFrames> frames;
  };
  struct Slot {
    int window = 0;
    bool open = false;
    std::vector<Era> eras;  // oldest first, at most two
  };
  Era& era_for(Slot& slot, int frame);
  void start_era(Slot& slot, std::unique_ptr<DesktopSource> source, int from);

  int pipeservers_ = 0;
  std::vector<Slot> slots_;
  std::vector<std::vector<Rect>> tiles_;  // by pipeserver: its tiles' canvas rectangles
  std::vector<std::string> opened_;       // the summary's lines
};

}  // namespace l2
