#include "pipeserver/picture_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>
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

SourceView fixed_view(const FixedView& fixed, int source_width, int source_height,
                      const Canvas& canvas, SourceFit fit) {
  const double w = source_width, h = source_height;
  const auto [fit_x, fit_y] = fitted_scale(w, h, canvas, fit);
  const double sx = fixed.zoom > 0 ? 1.0 / fixed.zoom : fit_x;
  const double sy = fixed.zoom > 0 ? 1.0 / fixed.zoom : fit_y;
  return {fixed.x.value_or(w / 2.0), fixed.y.value_or(h / 2.0), sx, sy};
}

bool parse_pan(std::string_view text, FixedView& fixed) {
  const std::size_t comma = text.find(',');
  if (comma == std::string_view::npos) return false;
  const auto number = [](std::string_view part, double& out) {
    const std::string s(part);
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return !s.empty() && end == s.c_str() + s.size() && std::isfinite(out);
  };
  double x = 0, y = 0;
  if (!number(text.substr(0, comma), x) || !number(text.substr(comma + 1), y)) return false;
  fixed.x = x;
  fixed.y = y;
  return true;
}

SourceView movie_view(int source_width, int source_height, const Canvas& canvas, SourceFit fit) {
  const double w = source_width, h = source_height;
  const auto [sx, sy] = fitted_scale(w, h, canvas, fit);
  // 1:1 puts the source's top-left pixel at the canvas's: canvas pixel X shows source pixel
  // floor(W / 2 + X + 0.5 - W / 2) = X.
  if (fit == SourceFit::OneToOne) return {canvas.width / 2.0, canvas.height / 2.0, sx, sy};
  return {w / 2.0, h / 2.0, sx, sy};
}

long source_index(double centre, double scale, int size, int x) {
  return static_cast<long>(std::floor(centre + (x + 0.5 - size / 2.0) * scale));
}

int mip_level(const SourceView& view, int levels) {
  const double finest = std::min(view.scale_x, view.scale_y);
  int level = 0;
  // Doubling, not log2: 2^L <= scale decided exactly, the same on every machine.
  while (level + 1 < levels && std::ldexp(1.0, level + 1) <= finest) ++level;
  return level;
}

long level_index(long index, int size, int level, int level_size) {
  if (index < 0 || index >= size) return -1;
  return std::min(index >> level, static_cast<long>(level_size) - 1);
}

namespace {

// The source indices [first, last + 1) pixels [begin, end) of an axis show inside [0, size):
// scales are positive, so the index grows with the pixel, and the first pixel at or past 0 and
// the last before `size` bound them (found by bisection). first >= last: none.
std::pair<long, long> sampled_span(double centre, double scale, int canvas_size, int begin, int end,
                                   int size) {
  const auto index = [&](int x) { return source_index(centre, scale, canvas_size, x); };
  // The first pixel in [lo, hi) whose index passes `reached`, or hi.
  const auto first_where = [](int lo, int hi, const auto& reached) {
    while (lo < hi) {
      const int mid = lo + (hi - lo) / 2;
      if (reached(mid)) {
        hi = mid;
      } else {
        lo = mid + 1;
      }
    }
    return lo;
  };
  const int in = first_where(begin, end, [&](int x) { return index(x) >= 0; });
  const int out = first_where(in, end, [&](int x) { return index(x) >= size; });
  if (in >= out) return {0, 0};
  return {index(in), index(out - 1) + 1};
}

}  // namespace

Rect sampled_source(const SourceView& view, int source_width, int source_height,
                    const Canvas& canvas, const Rect& on_canvas) {
  const auto [x0, x1] = sampled_span(view.centre_x, view.scale_x, canvas.width, on_canvas.x,
                                     on_canvas.right(), source_width);
  const auto [y0, y1] = sampled_span(view.centre_y, view.scale_y, canvas.height, on_canvas.y,
                                     on_canvas.bottom(), source_height);
  if (x1 <= x0 || y1 <= y0) return {};
  return {static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1 - x0),
          static_cast<int>(y1 - y0)};
}

}  // namespace l2
