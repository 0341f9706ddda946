#include "balance/cost_estimate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace l2 {
namespace {

// The cost of a band from its top (left) edge up to each position along one axis: the
// patches' pixels, linear between their edges, and the price of every footprint that starts
// before the position. A part [a, c] of the band costs pixels(a..c) plus every footprint that
// starts before c and ends after a.
class AxisCost {
 public:
  AxisCost(const std::vector<CostPatch>& patches, const Footprints& footprints, double per_triangle,
           const Rect& band, bool along_y)
      : lo_(along_y ? band.y : band.x), hi_(along_y ? band.bottom() : band.right()) {
    std::vector<std::array<double, 2>> starts;  // position, price
    for (const BatchFootprint& f : footprints) {
      const Rect o = intersect(f.on_canvas, band);
      const double price = per_triangle * f.triangles;
      if (o.empty() || price <= 0) continue;
      starts.push_back({double(along_y ? o.y : o.x), price});
      ends_.push_back({double(along_y ? o.bottom() : o.right()), price});
    }
    std::vector<double> at{lo_, hi_};
    for (const CostPatch& p : patches) {
      const Rect o = intersect(p.on_canvas, band);
      if (o.empty()) continue;
      at.push_back(along_y ? o.y : o.x);
      at.push_back(along_y ? o.bottom() : o.right());
      slopes_.push_back(
          {double(at[at.size() - 2]), double(at.back()), p.per_pixel * (along_y ? o.w : o.h)});
    }
    for (const auto& s : starts) at.push_back(s[0]);
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    std::sort(starts.begin(), starts.end());
    std::sort(ends_.begin(), ends_.end());
    double started = 0;
    std::size_t next = 0;
    for (const double t : at) {
      while (next < starts.size() && starts[next][0] <= t) started += starts[next++][1];
      points_.push_back({t, pixels_exact(t), started});
    }
    priced_ = !starts.empty();
  }

  double lo() const { return lo_; }
  double hi() const { return hi_; }
  bool priced() const { return priced_; }

  double part(double a, double c) const {
    return pixels(c) - pixels(a) + started_before(c) - ended_by(a);
  }

  // The smallest c from a on where part(a, c) reaches `want`; hi when it never does. A step
  // (a footprint starting at m) that would carry the part past `want` cuts at m, leaving the
  // footprint to the next part.
  double reach(double a, double want) const {
    const double target = want + pixels(a) + ended_by(a);
    for (std::size_t k = 0; k + 1 < points_.size(); ++k) {
      const Point& m = points_[k];
      const Point& n = points_[k + 1];
      if (n.t <= a) continue;
      // Within (m, n] no footprint starts: the value rises with the pixels alone.
      const double from = std::max(m.t, a), from_pixels = pixels(from);
      const double after = from_pixels + m.started;
      if (after >= target) return from;
      if (n.pixels + m.started >= target) {
        return from + (target - after) / (n.pixels - from_pixels) * (n.t - from);
      }
    }
    return hi_;
  }

 private:
  struct Point {
    double t, pixels, started;  // started: the price of footprints starting at or before t
  };

  double pixels_exact(double t) const {
    double sum = 0;
    for (const auto& [from, to, per_unit] : slopes_)
      sum += per_unit * (std::clamp(t, from, to) - from);
    return sum;
  }
  double pixels(double t) const {
    const auto it = std::lower_bound(points_.begin(), points_.end(), t,
                                     [](const Point& p, double v) { return p.t < v; });
    if (it == points_.end()) return points_.back().pixels;
    if (it->t == t || it == points_.begin()) return it->pixels;
    const Point& m = *(it - 1);
    return m.pixels + (it->pixels - m.pixels) * (t - m.t) / (it->t - m.t);
  }
  double started_before(double t) const {
    const auto it = std::lower_bound(points_.begin(), points_.end(), t,
                                     [](const Point& p, double v) { return p.t < v; });
    return it == points_.begin() ? 0 : (it - 1)->started;
  }
  double ended_by(double t) const {
    double sum = 0;
    for (const auto& [end, price] : ends_) {
      if (end > t) break;
      sum += price;
    }
    return sum;
  }

  double lo_, hi_;
  bool priced_ = false;
  std::vector<std::array<double, 3>> slopes_;  // from, to, cost per unit along the axis
  std::vector<std::array<double, 2>> ends_;    // position, price; ascending
  std::vector<Point> points_;
};

// The edges of `parts` parts no dearer than `most` each, cut greedily from the top (left);
// the last part takes the rest.
std::vector<double> greedy_cuts(const AxisCost& axis, int parts, double most) {
  std::vector<double> cuts;
  double a = axis.lo();
  for (int k = 1; k < parts; ++k) cuts.push_back(a = axis.reach(a, most));
  return cuts;
}

// Each display draws its tiles in its own window: a batch across a mullion is drawn again on
// each side, so its footprint counts once per display it reaches.
Footprints per_display(const Wall& wall, const Footprints& footprints) {
  Footprints out;
  for (const BatchFootprint& f : footprints) {
    for (const Display& d : wall.displays) {
      const Rect o = intersect(f.on_canvas, d.on_canvas());
      if (!o.empty()) out.push_back({o, f.triangles});
    }
  }
  return out;
}

}  // namespace

CostEstimate::CostEstimate(std::vector<CostPatch> patches, Footprints footprints,
                           double per_triangle)
    : patches_(std::move(patches)),
      footprints_(std::move(footprints)),
      per_triangle_(std::max(per_triangle, 0.0)) {
  for (const CostPatch& p : patches_) total_ += p.per_pixel * double(p.on_canvas.area());
  for (const BatchFootprint& f : footprints_) total_ += per_triangle_ * f.triangles;
  if (total_ > 0) return;
  for (CostPatch& p : patches_) p.per_pixel = 1;
  total_ = 0;
  for (const CostPatch& p : patches_) total_ += double(p.on_canvas.area());
}

double fit_per_triangle(const std::vector<TileSample>& tiles) {
  // Normal equations of seconds ≈ x0 + x1·pixels + x2·triangles, solved by Cramer's rule.
  std::array<std::array<double, 3>, 3> m{};
  std::array<double, 3> v{};
  double cheapest = std::numeric_limits<double>::infinity();
  for (const TileSample& t : tiles) {
    const std::array<double, 3> row{1, t.pixels, t.triangles};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m[i][j] += row[i] * row[j];
      v[i] += row[i] * t.seconds;
    }
    if (t.triangles > 0) cheapest = std::min(cheapest, std::max(t.seconds, 0.0) / t.triangles);
  }
  if (tiles.size() < 4 || !std::isfinite(cheapest)) return 0;
  const auto det = [](const std::array<std::array<double, 3>, 3>& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double d = det(m);
  if (!std::isfinite(d) || std::abs(d) < 1e-12 * std::abs(m[0][0] * m[1][1] * m[2][2])) return 0;
  auto with_v = m;
  for (int i = 0; i < 3; ++i) with_v[i][2] = v[i];
  return std::clamp(det(with_v) / d, 0.0, cheapest);
}

CostEstimate CostEstimate::from_layout(const TileLayout& layout, const TileSeconds& seconds,
                                       const Footprints& batches) {
  const Footprints footprints = per_display(layout.wall, batches);
  if (seconds.size() != layout.pipeservers.size()) {
    throw std::invalid_argument("render times: one list per pipeserver needed");
  }
  std::vector<TileSample> samples;
  std::vector<Rect> rects;
  for (std::size_t s = 0; s < seconds.size(); ++s) {
    const auto& tiles = layout.pipeservers[s].tiles;
    if (seconds[s].size() != tiles.size()) {
      throw std::invalid_argument("render times: one time per packed tile needed");
    }
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      const Rect r = tiles[i].tile.on_canvas;
      double touched = 0;
      for (const BatchFootprint& f : footprints) {
        if (!intersect(f.on_canvas, r).empty()) touched += f.triangles;
      }
      samples.push_back({std::max(seconds[s][i], 0.0), double(r.area()), touched});
      rects.push_back(r);
    }
  }
  const double per_triangle = fit_per_triangle(samples);
  std::vector<CostPatch> patches;
  for (std::size_t i = 0; i < rects.size(); ++i) {
    const double rest = samples[i].seconds - per_triangle * samples[i].triangles;
    patches.push_back({rects[i], std::max(rest, 0.0) / samples[i].pixels});
  }
  return CostEstimate(std::move(patches), per_triangle > 0 ? footprints : Footprints{},
                      per_triangle);
}

double CostEstimate::cost(const Rect& r) const {
  double sum = 0;
  for (const CostPatch& p : patches_) sum += p.per_pixel * double(intersect(p.on_canvas, r).area());
  for (const BatchFootprint& f : footprints_) {
    if (!intersect(f.on_canvas, r).empty()) sum += per_triangle_ * f.triangles;
  }
  return sum;
}

CostEstimate CostEstimate::spread() const {
  std::vector<CostPatch> patches = patches_;
  for (const BatchFootprint& f : footprints_) {
    if (f.on_canvas.empty()) continue;
    patches.push_back({f.on_canvas, per_triangle_ * f.triangles / double(f.on_canvas.area())});
  }
  return CostEstimate(std::move(patches));
}

std::vector<double> CostEstimate::cuts(const Rect& band, int parts, bool along_y) const {
  if (parts <= 1) return {};
  const AxisCost axis(patches_, footprints_, per_triangle_, band, along_y);
  const double whole = axis.part(axis.lo(), axis.hi());
  if (!axis.priced()) {
    std::vector<double> out;
    for (int k = 1; k < parts; ++k) out.push_back(axis.reach(axis.lo(), whole * k / parts));
    return out;
  }
  // The least "most a part costs" that greedy cutting still fits into `parts` parts.
  double fits = whole, short_of = whole / parts;
  for (int step = 0; step < 50 && fits - short_of > 1e-9 * whole; ++step) {
    const double most = 0.5 * (fits + short_of);
    const std::vector<double> c = greedy_cuts(axis, parts, most);
    (axis.part(c.back(), axis.hi()) <= most ? fits : short_of) = most;
  }
  return greedy_cuts(axis, parts, fits);
}

std::vector<double> CostEstimate::cuts_y(const Rect& band, int parts) const {
  return cuts(band, parts, true);
}

std::vector<double> CostEstimate::cuts_x(const Rect& band, int parts) const {
  return cuts(band, parts, false);
}

}  // namespace l2
