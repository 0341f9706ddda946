// The cost grid a k-d re-split reads (tilelayout's `kind = "kd"` with `cost`): the estimate
// as seconds per visible pixel of each cell.
#pragma once

#include <vector>

#include "balance/cost_estimate.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

// `rows` x `columns` cells over the canvas with tilelayout's cell edges (size * i / cells).
// A cell's value is its estimated cost over the pixels of it that displays show, since the
// planner charges only those; a cell no display shows is 0.
std::vector<std::vector<double>> kd_cost_grid(const Wall& wall, const CostEstimate& estimate,
                                              int columns, int rows);

// `previous` moved toward `measured` by `gain` per cell (the damping of edge motion, for the
// whole grid); `measured` alone when the shapes differ.
std::vector<std::vector<double>> blend_grids(const std::vector<std::vector<double>>& previous,
                                             const std::vector<std::vector<double>>& measured,
                                             double gain);

}  // namespace l2
