// How a tile edge moves toward its balanced position: a velocity proportional to the distance
// left, so it settles in about five frames without overshooting (the damping that keeps edges
// from oscillating when the estimate lags the layout), and not at all within a dead band, so
// timing noise does not re-tile every frame.
#pragma once

#include <vector>

namespace l2 {

struct EdgeMotion {
  double gain = 0.5;     // fraction of the distance covered per frame: 1/32 left after 5 frames
  double dead_band = 2;  // pixels: an edge this close to its target stays
};

// The edge's position in the next frame.
double move_edge(double position, double target, const EdgeMotion& motion);

// Edges as integer pixel positions 0 = e[0] < e[1] < ... < e[n] = size: rounded, then pushed
// apart so every cell keeps at least one pixel. `edges` holds e[0..n] with e[0] and e[n] fixed.
std::vector<int> pixel_edges(const std::vector<double>& edges);

}  // namespace l2
