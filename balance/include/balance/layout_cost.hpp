// What a layout is predicted to take, for deciding whether a new one pays (resistance). Each
// display tile costs a fixed part, whatever its pixels (its clear, the GL set-up, every batch
// its footprint touches drawn again), plus its pixels' share of the rest: the uniform estimate
// alone says a tiling cut into more tiles costs the same in all, and it does not.
#pragma once

#include "balance/cost_estimate.hpp"

namespace l2 {

// The fixed part of a display tile: `fraction` of the mean measured tile time of `seconds`.
double tile_overhead(const TileSeconds& seconds, double fraction);

// The last frame's times less `overhead` a tile (not below 0), as CostEstimate::from_layout
// estimates them: the part of the cost that follows the pixels and the footprints touched.
CostEstimate pixel_estimate(const TileLayout& layout, const TileSeconds& seconds, double overhead,
                            const Footprints& footprints = {});

// A layout's predicted render times, each pipeserver's the sum over its display tiles of
// `overhead` plus the tile's pixels' (and footprints') cost under `estimate`: the slowest
// pipeserver's (the frame, where each has cores of its own; on the layout the estimate was
// measured on, with the same overhead, the measured frame time) and all of them summed (the
// frame's render work, which sets the frame rate where pipeservers share cores).
struct FramePrediction {
  double slowest = 0;
  double work = 0;
};
FramePrediction predict_frame(const TileLayout& layout, const CostEstimate& estimate,
                              double overhead);

}  // namespace l2
