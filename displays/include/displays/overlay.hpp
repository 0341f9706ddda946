// The overlay line of the wall window ("frame 12  59.8 fps  latency 1 frame") and the frame
// rate behind it. Pure: the caller owns the clock, so tests feed exact times.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>

#include "image/rgb_image.hpp"

namespace l2 {

struct FrameInfo {
  std::int64_t frame = 0;             // the application frame on the displays
  double fps = 0.0;                   // displayed frames per second, 0 while unknown
  std::optional<int> latency_frames;  // scan-out to display, in frames (spec §6: 1); unknown: none
  bool paused = false;
};

// "frame 12  59.8 fps  latency 1 frame", with "  paused" appended while paused.
std::string overlay_line(const FrameInfo& info);

// The overlay bar: `line` in light grey on the mullion colour, width x height pixels.
RgbImage render_overlay(const std::string& line, int width, int height);

// Frames per second over the last `window` frames: steady enough to read, quick to follow.
class FpsMeter {
 public:
  using Clock = std::chrono::steady_clock;
  explicit FpsMeter(std::size_t window = 30) : window_(window < 2 ? 2 : window) {}

  void tick(Clock::time_point now);
  double fps() const;  // 0 until two frames have been seen

 private:
  std::size_t window_;
  std::deque<Clock::time_point> times_;
};

}  // namespace l2
