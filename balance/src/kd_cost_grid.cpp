#include "balance/kd_cost_grid.hpp"

namespace l2 {

std::vector<std::vector<double>> kd_cost_grid(const Wall& wall, const CostEstimate& estimate,
                                              int columns, int rows) {
  // The cells are not drawn one by one: a footprint's price belongs to its pixels here.
  const CostEstimate spread = estimate.spread();
  std::vector<std::vector<double>> grid(static_cast<std::size_t>(rows),
                                        std::vector<double>(static_cast<std::size_t>(columns)));
  const long long w = wall.canvas_width, h = wall.canvas_height;
  for (long long j = 0; j < rows; ++j) {
    const int y0 = static_cast<int>(h * j / rows), y1 = static_cast<int>(h * (j + 1) / rows);
    for (long long i = 0; i < columns; ++i) {
      const int x0 = static_cast<int>(w * i / columns);
      const int x1 = static_cast<int>(w * (i + 1) / columns);
      const Rect cell{x0, y0, x1 - x0, y1 - y0};
      long long visible = 0;
      for (const Display& d : wall.displays) visible += intersect(cell, d.on_canvas()).area();
      grid[j][i] = visible > 0 ? spread.cost(cell) / double(visible) : 0.0;
    }
  }
  return grid;
}

std::vector<std::vector<double>> blend_grids(const std::vector<std::vector<double>>& previous,
                                             const std::vector<std::vector<double>>& measured,
                                             double gain) {
  if (previous.size() != measured.size() || previous.empty() ||
      previous[0].size() != measured[0].size()) {
    return measured;
  }
  std::vector<std::vector<double>> out = previous;
  for (std::size_t j = 0; j < out.size(); ++j) {
    for (std::size_t i = 0; i < out[j].size(); ++i) {
      out[j][i] += gain * (measured[j][i] - previous[j][i]);
    }
  }
  return out;
}

}  // namespace l2
