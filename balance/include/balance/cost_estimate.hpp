// What rendering a canvas rectangle costs, estimated from the last frame: each tile's render
// time spread uniformly over its pixels (Abraham et al.'s estimate for load-balanced
// sort-first rendering), less what the batches it touched cost it. A batch is drawn again in
// every tile its footprint touches, so a thin tile through a dense cloud pays for the whole
// cloud's batches: the estimate prices a rectangle as its pixels plus a price per triangle of
// every footprint it touches, the price fitted to the frame's tiles.
#pragma once

#include <vector>

#include "tilelayout/batch_footprint.hpp"
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
  // Patches may overlap: their costs add. All zero (nothing measured yet) counts every patch pixel
  // alike, so the cuts below fall by area. `per_triangle`: what a footprint's triangle adds to
  // every rectangle the footprint touches.
  explicit CostEstimate(std::vector<CostPatch> patches, Footprints footprints = {},
                        double per_triangle = 0);
  // The price per triangle fitted to the tiles' times (none without footprints), the rest of
  // each tile's time spread over its pixels. A footprint across displays counts once on each
  // (every display's tiles are drawn in a window of their own). Throws std::invalid_argument when
  // `seconds` does not have the layout's shape.
  static CostEstimate from_layout(const TileLayout& layout, const TileSeconds& seconds,
                                  const Footprints& footprints = {});

  double cost(const Rect& r) const;
  // Everything drawn once: the patches and every footprint's triangles.
  double total() const { return total_; }
  double per_triangle() const { return per_triangle_; }
  // The footprints' price spread over their pixels, as one more patch each: the same total,
  // for cutting a grid of cells that are not drawn one by one (the k-d cost grid).
  CostEstimate spread() const;

  // The parts - 1 inner edges, ascending, that cut `band` into `parts` rows (cuts_y) or columns
  // (cuts_x) of equal cost; where a footprint's step stands in the way, the cut with the
  // cheapest largest part. Exact between patch edges when no footprint is priced.
  std::vector<double> cuts_y(const Rect& band, int parts) const;
  std::vector<double> cuts_x(const Rect& band, int parts) const;

 private:
  std::vector<double> cuts(const Rect& band, int parts, bool along_y) const;

  std::vector<CostPatch> patches_;
  Footprints footprints_;
  double per_triangle_ = 0;
  double total_ = 0;
};

// The price per triangle of a footprint touching a tile, by least squares over the tiles:
// seconds ≈ fixed + per pixel·pixels + per triangle·triangles touched. Kept from 0 up to where
// the tile that is cheapest for its triangles would be left no time for its pixels; 0 with
// fewer tiles than the fit needs.
struct TileSample {
  double seconds = 0, pixels = 0, triangles = 0;
};
double fit_per_triangle(const std::vector<TileSample>& tiles);

}  // namespace l2
