#include "pipeserver/picture_view.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace l2 {

namespace {

// Frames of the pan's two sweeps: neither divides the other or the zoom's period, so the path
// does not repeat the same few views.
constexpr int kPanPeriodX = 450;
constexpr int kPanPeriodY = 750;

double phase(int frame, int period) {
  return 2.0 * std::numbers::pi * static_cast<double>(frame % period) / period;
}

}  // namespace

SourceView picture_view(int frame, int source_width, int source_height, const Canvas& canvas) {
  const double w = source_width, h = source_height;
  const double cover = std::min(w / canvas.width, h / canvas.height);
  const double near = std::min(1.0, cover);
  const double t = (1.0 - std::cos(phase(frame, kPictureZoomPeriod))) / 2.0;
  const double scale = cover * std::pow(near / cover, t);
  // The centre moves as far as the canvas stays covered: half the source less half the view.
  const double reach_x = std::max(0.0, (w - canvas.width * scale) / 2.0);
  const double reach_y = std::max(0.0, (h - canvas.height * scale) / 2.0);
  return {w / 2.0 + reach_x * std::sin(phase(frame, kPanPeriodX)),
          h / 2.0 + reach_y * std::sin(phase(frame, kPanPeriodY)), scale};
}

SourceView movie_view(int source_width, int source_height, const Canvas& canvas) {
  const double w = source_width, h = source_height;
  return {w / 2.0, h / 2.0, std::max(w / canvas.width, h / canvas.height)};
}

}  // namespace l2
