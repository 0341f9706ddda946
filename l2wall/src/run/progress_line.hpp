#pragma once

#include <optional>

#include "run_core.hpp"

namespace l2 {

// The progress line of a live run on stderr: frames on the displays and the frame rate, and
// before the first frames a line a second saying what the run waits for. It owns that line and
// nothing else: it reads where the frames are and changes none of the run.
class ProgressLine {
 public:
  explicit ProgressLine(const RunCore& core) : core_(core) {}

  // After a swap: frame k/N and the frame rate so far.
  void frames(RunClock::time_point now);
  // Before the first frames, which wait for each pipeserver to read its model or picture (a
  // large one takes seconds): a line a second, so a slow start is seen as one, not a hang.
  void waiting();
  // Whether a progress line is on stderr (an error then starts a line of its own).
  bool shown() const { return shown_; }

 private:
  const RunCore& core_;
  bool shown_ = false;
  std::optional<RunClock::time_point> waiting_since_;  // the wait for the first frames
  int waiting_shown_ = 0;                              // its seconds last shown
};

}  // namespace l2
