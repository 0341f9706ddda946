#include "cost_map.hpp"

#include <algorithm>

namespace l2 {
namespace {

// Edges of `cells` equal cost cells over `size`, one per cell boundary (empty cells kept, so
// index i is cost column i).
std::vector<int> grid_edges(int size, std::size_t cells) {
  std::vector<int> e;
  for (std::size_t i = 0; i <= cells; ++i) e.push_back(static_cast<int>(size * i / cells));
  return e;
}

// The cost-grid edges plus the display edges, clipped, sorted and unique.
std::vector<int> cut_edges(int size, std::size_t cells, const std::vector<int>& display_edges) {
  std::vector<int> e = grid_edges(size, cells);
  for (int d : display_edges) e.push_back(std::clamp(d, 0, size));
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

}  // namespace

CostMap::CostMap(const Wall& wall) {
  const auto& grid = wall.tiling.cost;
  const std::size_t rows = grid.empty() ? 1 : grid.size();
  const std::size_t cols = grid.empty() ? 1 : grid[0].size();
  std::vector<int> dx, dy;
  for (const Display& d : wall.displays) {
    dx.insert(dx.end(), {d.on_canvas().x, d.on_canvas().right()});
    dy.insert(dy.end(), {d.on_canvas().y, d.on_canvas().bottom()});
  }
  xs_ = cut_edges(wall.canvas_width, cols, dx);
  ys_ = cut_edges(wall.canvas_height, rows, dy);
  // The cost cell of a pixel: the last cost-grid edge at or before it.
  const std::vector<int> gx = grid_edges(wall.canvas_width, cols);
  const std::vector<int> gy = grid_edges(wall.canvas_height, rows);
  const auto cell = [](const std::vector<int>& g, int v) {
    return static_cast<std::size_t>(std::upper_bound(g.begin(), g.end(), v) - g.begin() - 1);
  };
  const std::size_t nx = xs_.size(), ny = ys_.size();
  sums_.assign(nx * ny, 0.0);
  for (std::size_t j = 1; j < ny; ++j) {
    for (std::size_t i = 1; i < nx; ++i) {
      const int x = xs_[i - 1], y = ys_[j - 1];  // the cell's top-left pixel
      bool visible = false;
      for (const Display& d : wall.displays) visible = visible || d.on_canvas().contains(x, y);
      double density = 0;
      if (visible) {
        density = grid.empty() ? 1.0 : grid[cell(gy, y)][cell(gx, x)];
      }
      const double area = double(xs_[i] - xs_[i - 1]) * (ys_[j] - ys_[j - 1]);
      sums_[j * nx + i] = density * area + sums_[(j - 1) * nx + i] + sums_[j * nx + i - 1] -
                          sums_[(j - 1) * nx + i - 1];
    }
  }
}

double CostMap::integral(int x, int y) const {
  const std::size_t nx = xs_.size();
  // The cell [xs_[i], xs_[i+1]) holding x; the last edge belongs to the cell before it.
  const std::size_t i =
      std::min<std::size_t>(std::upper_bound(xs_.begin(), xs_.end(), x) - xs_.begin() - 1, nx - 2);
  const std::size_t j = std::min<std::size_t>(
      std::upper_bound(ys_.begin(), ys_.end(), y) - ys_.begin() - 1, ys_.size() - 2);
  const double fx = double(x - xs_[i]) / (xs_[i + 1] - xs_[i]);
  const double fy = double(y - ys_[j]) / (ys_[j + 1] - ys_[j]);
  const double f00 = sums_[j * nx + i], f10 = sums_[j * nx + i + 1];
  const double f01 = sums_[(j + 1) * nx + i], f11 = sums_[(j + 1) * nx + i + 1];
  return f00 * (1 - fx) * (1 - fy) + f10 * fx * (1 - fy) + f01 * (1 - fx) * fy + f11 * fx * fy;
}

double CostMap::cost(const Rect& r) const {
  return integral(r.right(), r.bottom()) - integral(r.x, r.bottom()) - integral(r.right(), r.y) +
         integral(r.x, r.y);
}

}  // namespace l2
