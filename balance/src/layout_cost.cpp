#include "balance/layout_cost.hpp"

#include <algorithm>

namespace l2 {

double tile_overhead(const TileSeconds& seconds, double fraction) {
  double sum = 0;
  std::size_t tiles = 0;
  for (const auto& pipeserver : seconds) {
    for (const double s : pipeserver) sum += std::max(s, 0.0);
    tiles += pipeserver.size();
  }
  return tiles == 0 ? 0 : fraction * sum / double(tiles);
}

CostEstimate pixel_estimate(const TileLayout& layout, const TileSeconds& seconds, double overhead,
                            const Footprints& footprints) {
  TileSeconds rest = seconds;
  for (auto& pipeserver : rest) {
    for (double& s : pipeserver) s = std::max(s - overhead, 0.0);
  }
  return CostEstimate::from_layout(layout, rest, footprints);
}

FramePrediction predict_frame(const TileLayout& layout, const CostEstimate& estimate,
                              double overhead) {
  FramePrediction f;
  for (const PipeserverPlan& p : layout.pipeservers) {
    double sum = 0;
    for (const PackedTile& t : p.tiles) sum += overhead + estimate.cost(t.tile.on_canvas);
    f.slowest = std::max(f.slowest, sum);
    f.work += sum;
  }
  return f;
}

}  // namespace l2
