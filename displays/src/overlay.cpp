#include "displays/overlay.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "displays/colours.hpp"
#include "image/label_text.hpp"

namespace l2 {

std::string overlay_line(const FrameInfo& info) {
  std::string line = fmt::format("frame {}  {:.1f} fps  latency ", info.frame, info.fps);
  if (info.latency_frames) {
    line += fmt::format("{} frame{}", *info.latency_frames, *info.latency_frames == 1 ? "" : "s");
  } else {
    line += "n/a";
  }
  if (info.paused) line += "  paused";
  return line;
}

RgbImage render_overlay(const std::string& line, int width, int height) {
  RgbImage bar(std::max(1, width), std::max(1, height), kMullionColour);
  // Twice the font size when there is room: readable on a large wall window.
  const int scale = height >= 2 * kTextHeight + 4 ? 2 : 1;
  const int y = std::max(0, (height - kTextHeight * scale) / 2);
  draw_text(bar, 4, y, line, kOverlayTextColour, scale);
  return bar;
}

void FpsMeter::tick(Clock::time_point now) {
  times_.push_back(now);
  while (times_.size() > window_) times_.pop_front();
}

double FpsMeter::fps() const {
  if (times_.size() < 2) return 0.0;
  const std::chrono::duration<double> span = times_.back() - times_.front();
  if (span.count() <= 0.0) return 0.0;
  return static_cast<double>(times_.size() - 1) / span.count();
}

}  // namespace l2
