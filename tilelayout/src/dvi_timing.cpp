#include "tilelayout/dvi_timing.hpp"

#include <algorithm>
#include <cmath>

namespace l2 {
namespace {

constexpr double kMinVerticalBlankUs = 460.0;
constexpr int kHorizontalBlank = 160;
constexpr int kCellPixels = 8;
constexpr int kFrontPorchLines = 3, kMinBackPorchLines = 6;
constexpr double kClockStepMhz = 0.25;

// CVT's vertical sync width says the aspect ratio: 4:3, 16:9, 16:10, 5:4 or 15:9, else 10.
int vsync_lines(int width, int height) {
  if (height % 3 == 0 && height * 4 / 3 == width) return 4;
  if (height % 9 == 0 && height * 16 / 9 == width) return 5;
  if (height % 10 == 0 && height * 16 / 10 == width) return 6;
  if (height % 4 == 0 && height * 5 / 4 == width) return 7;
  if (height % 9 == 0 && height * 15 / 9 == width) return 7;
  return 10;
}

}  // namespace

int DviTiming::links() const {
  if (pixel_clock_mhz <= kSingleLinkDviMhz) return 1;
  return pixel_clock_mhz <= kDualLinkDviMhz ? 2 : 0;
}

DviTiming dvi_timing(int width, int height, int refresh_hz) {
  const int active_width = (width + kCellPixels - 1) / kCellPixels * kCellPixels;
  // The line period if the blanking were exactly the minimum, then the blanking in whole lines.
  const double line_us = (1e6 / refresh_hz - kMinVerticalBlankUs) / height;
  const int blank_lines =
      std::max(static_cast<int>(kMinVerticalBlankUs / line_us) + 1,
               kFrontPorchLines + vsync_lines(active_width, height) + kMinBackPorchLines);
  DviTiming t;
  t.h_total = active_width + kHorizontalBlank;
  t.v_total = height + blank_lines;
  const double mhz = double(refresh_hz) * t.v_total * t.h_total / 1e6;
  t.pixel_clock_mhz = std::floor(mhz / kClockStepMhz) * kClockStepMhz;
  return t;
}

int max_refresh_hz(int width, int height, double link_mhz) {
  // The clock grows with the rate: the last rate before the first that does not fit.
  int hz = 0;
  while (hz < 1000 && dvi_timing(width, height, hz + 1).pixel_clock_mhz <= link_mhz) ++hz;
  return hz;
}

}  // namespace l2
