#include "balance/cost_estimate.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>

namespace l2 {
namespace {

// The t in lo..hi where the increasing, piecewise linear `f` (linear between `edges`) reaches
// `part`; hi when it never does.
double invert(double lo, double hi, std::vector<double> edges, double part,
              const std::function<double(double)>& f) {
  edges.push_back(lo);
  edges.push_back(hi);
  std::erase_if(edges, [&](double e) { return e < lo || e > hi; });
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  double prev = f(edges[0]);
  for (std::size_t k = 1; k < edges.size(); ++k) {
    const double next = f(edges[k]);
    if (next >= part && next > prev) {
      return edges[k - 1] + (part - prev) / (next - prev) * (edges[k] - edges[k - 1]);
    }
    prev = next;
  }
  return hi;
}

// The cost of the part of `r` from its left or top edge to the fractional position t.
double partial_cost(const std::vector<CostPatch>& patches, const Rect& r, bool along_y, double t) {
  double sum = 0;
  for (const CostPatch& p : patches) {
    const Rect o = intersect(p.on_canvas, r);
    if (o.empty()) continue;
    const double lo = along_y ? o.y : o.x, hi = along_y ? o.bottom() : o.right();
    const double span = std::clamp(t, lo, hi) - lo;
    sum += p.per_pixel * span * (along_y ? o.w : o.h);
  }
  return sum;
}

double cut(const std::vector<CostPatch>& patches, const Rect& band, bool along_y, double part) {
  std::vector<double> edges;
  for (const CostPatch& p : patches) {
    edges.push_back(along_y ? p.on_canvas.y : p.on_canvas.x);
    edges.push_back(along_y ? p.on_canvas.bottom() : p.on_canvas.right());
  }
  const double lo = along_y ? band.y : band.x, hi = along_y ? band.bottom() : band.right();
  return invert(lo, hi, edges, part,
                [&](double t) { return partial_cost(patches, band, along_y, t); });
}

}  // namespace

CostEstimate::CostEstimate(std::vector<CostPatch> patches) : patches_(std::move(patches)) {
  for (const CostPatch& p : patches_) total_ += p.per_pixel * double(p.on_canvas.area());
  if (total_ > 0) return;
  for (CostPatch& p : patches_) p.per_pixel = 1;
  total_ = 0;
  for (const CostPatch& p : patches_) total_ += double(p.on_canvas.area());
}

CostEstimate CostEstimate::from_layout(const TileLayout& layout, const TileSeconds& seconds) {
  if (seconds.size() != layout.pipeservers.size()) {
    throw std::invalid_argument("render times: one list per pipeserver needed");
  }
  std::vector<CostPatch> patches;
  for (std::size_t s = 0; s < seconds.size(); ++s) {
    const auto& tiles = layout.pipeservers[s].tiles;
    if (seconds[s].size() != tiles.size()) {
      throw std::invalid_argument("render times: one time per packed tile needed");
    }
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      const Rect r = tiles[i].tile.on_canvas;
      patches.push_back({r, std::max(seconds[s][i], 0.0) / double(r.area())});
    }
  }
  return CostEstimate(std::move(patches));
}

double CostEstimate::cost(const Rect& r) const {
  double sum = 0;
  for (const CostPatch& p : patches_) sum += p.per_pixel * double(intersect(p.on_canvas, r).area());
  return sum;
}

double CostEstimate::cut_y(const Rect& band, double part) const {
  return cut(patches_, band, true, part);
}

double CostEstimate::cut_x(const Rect& band, double part) const {
  return cut(patches_, band, false, part);
}

}  // namespace l2
