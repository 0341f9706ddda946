// `lightning2_emu sequence --show window|monitors`: a captured sequence played on screen,
// refresh by refresh, with the timing of spec §6. Refresh t shows what the displays show during
// refresh t (the frames scanned out during refresh t-1) for 1/HZ s. Keys as in the wall window:
// space pauses, s saves what the screens show into OUT/screenshots/, q or Esc stop the sequence
// at that refresh (the report then covers the refreshes run).
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "displays/overlay.hpp"
#include "displays/wall_presenter.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

// The wall the window lays out: the wall file's, or with --displays the displays in a row
// 16 pixels apart, display i on monitor i (its index in GLFW's list).
Wall wall_to_show(const CommonOptions& o, const Setup& setup);

class SequenceShow {
 public:
  // Opens the window(s); throws DisplayError (one line) without a screen or monitors.
  SequenceShow(const CommonOptions& o, const Setup& setup, const ShowOptions& show);
  ~SequenceShow();
  SequenceShow(const SequenceShow&) = delete;
  SequenceShow& operator=(const SequenceShow&) = delete;

  // Shows refresh t (display(id): what display id shows now) and keeps it up for its refresh
  // period, acting on keys meanwhile; false once the user quit.
  bool play(int t, const std::vector<const RgbImage*>& by_id);

 private:
  void act(UserAction a);
  void wait_for_next_refresh();

  Wall wall_;
  ShowOptions options_;
  std::filesystem::path out_;
  std::unique_ptr<WallPresenter> presenter_;
  std::vector<RgbImage> images_;
  FrameInfo info_;
  FpsMeter meter_;
  bool paused_ = false, quit_ = false;
  std::chrono::steady_clock::duration period_{};
  std::chrono::steady_clock::time_point next_{};
};

}  // namespace l2
