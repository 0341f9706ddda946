#include "pipeserver/picture_view.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace l2 {

namespace {

// Frames of the pan's two sweeps: neither divides the other or the zoom's period, so the path
// does not repeat the same few views.
constexpr int kPanPeriodX = 450;
constexpr int kPanPeriodY = 750;

double phase(int frame, int period) {
  return 2.0 * std::numbers::pi * static_cast<double>(frame % period) / period;
}

// Source pixels per canvas pixel, across and down, for the frame-0 view.
std::pair<double, double> fitted_scale(double w, double h, const Canvas& canvas, SourceFit fit) {
  const double across = w / canvas.width, down = h / canvas.height;
  switch (fit) {
    case SourceFit::Fit:
      return {std::max(across, down), std::max(across, down)};
    case SourceFit::Fill:
      return {std::min(across, down), std::min(across, down)};
    case SourceFit::Stretch:
      return {across, down};
    case SourceFit::OneToOne:
      return {1.0, 1.0};
  }
  return {across, down};
}

}  // namespace

std::optional<SourceFit> parse_source_fit(std::string_view name) {
  if (name == "fit") return SourceFit::Fit;
  if (name == "fill") return SourceFit::Fill;
  if (name == "stretch") return SourceFit::Stretch;
  if (name == "1:1") return SourceFit::OneToOne;
  return std::nullopt;
}

SourceView picture_view(int frame, int source_width, int source_height, const Canvas& canvas,
                        SourceFit fit) {
  const double w = source_width, h = source_height;
  const auto [start_x, start_y] = fitted_scale(w, h, canvas, fit);
  const double t = (1.0 - std::cos(phase(frame, kPictureZoomPeriod))) / 2.0;
  // Each axis zooms from its frame-0 scale to 1:1 (or stays, when the picture is smaller).
  const auto zoom = [t](double start) { return start * std::pow(std::min(1.0, start) / start, t); };
  const double sx = zoom(start_x), sy = zoom(start_y);
  // The centre moves as far as the view stays inside the source: half the source less half the
  // view.
  const double reach_x = std::max(0.0, (w - canvas.width * sx) / 2.0);
  const double reach_y = std::max(0.0, (h - canvas.height * sy) / 2.0);
  return {w / 2.0 + reach_x * std::sin(phase(frame, kPanPeriodX)),
          h / 2.0 + reach_y * std::sin(phase(frame, kPanPeriodY)), sx, sy};
}

SourceView movie_view(int source_width, int source_height, const Canvas& canvas, SourceFit fit) {
  const double w = source_width, h = source_height;
  const auto [sx, sy] = fitted_scale(w, h, canvas, fit);
  // 1:1 puts the source's top-left pixel at the canvas's: canvas pixel X shows source pixel
  // floor(W / 2 + X + 0.5 - W / 2) = X.
  if (fit == SourceFit::OneToOne) return {canvas.width / 2.0, canvas.height / 2.0, sx, sy};
  return {w / 2.0, h / 2.0, sx, sy};
}

}  // namespace l2
