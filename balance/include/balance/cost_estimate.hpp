// What rendering a canvas rectangle costs, estimated from the last frame: each tile's render
// time spread uniformly over its pixels (Abraham et al.'s estimate for load-balanced
// sort-first rendering).
#pragma once

#include <vector>

#include "tilelayout/tile_layout.hpp"

namespace l2 {

// Render seconds of every packed tile of the last frame: seconds[s][i] is
// layout.pipeservers[s].tiles[i], as each pipeserver measures and reports them.
using TileSeconds = std::vector<std::vector<double>>;

// A canvas rectangle rendered at a constant cost per pixel.
struct CostPatch {
  Rect on_canvas;
  double per_pixel = 0;
};

class CostEstimate {
 public:
  // Patches must not overlap. All zero (nothing measured yet) counts every patch pixel alike,
  // so the cuts below fall by area.
  explicit CostEstimate(std::vector<CostPatch> patches);
  // Throws std::invalid_argument when `seconds` does not have the layout's shape.
  static CostEstimate from_layout(const TileLayout& layout, const TileSeconds& seconds);

  double cost(const Rect& r) const;
  double total() const { return total_; }
  // The row y in band.y..band.bottom() where the rows of `band` above y cost `part`. The cost
  // grows linearly between patch edges, so y is exact between them.
  double cut_y(const Rect& band, double part) const;
  // The same for columns: the x where the columns of `band` left of it cost `part`.
  double cut_x(const Rect& band, double part) const;

 private:
  std::vector<CostPatch> patches_;
  double total_ = 0;
};

}  // namespace l2
