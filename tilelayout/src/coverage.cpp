// Coverage by coordinate compression: the tile edges cut a display into cells that are each
// covered by the same tiles, so counting per cell is exact and independent of display size.
#include "tilelayout/coverage.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace l2 {
namespace {

std::vector<int> edges(int size, const std::vector<const Rect*>& rects, bool horizontal) {
  std::vector<int> e = {0, size};
  for (const Rect* r : rects) {
    e.push_back(horizontal ? r->x : r->y);
    e.push_back(horizontal ? r->right() : r->bottom());
  }
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

int index_of(const std::vector<int>& e, int v) {
  return static_cast<int>(std::lower_bound(e.begin(), e.end(), v) - e.begin());
}

DisplayCoverage cover_one(const Display& d, const std::vector<const Rect*>& rects) {
  const std::vector<int> xs = edges(d.width, rects, true), ys = edges(d.height, rects, false);
  const std::size_t nx = xs.size(), ny = ys.size();
  // 2-D difference array over the compressed grid, then prefix sums give each cell's count.
  std::vector<int> count(nx * ny, 0);
  for (const Rect* r : rects) {
    const std::size_t x0 = index_of(xs, r->x), x1 = index_of(xs, r->right());
    const std::size_t y0 = index_of(ys, r->y), y1 = index_of(ys, r->bottom());
    count[y0 * nx + x0] += 1;
    count[y0 * nx + x1] -= 1;
    count[y1 * nx + x0] -= 1;
    count[y1 * nx + x1] += 1;
  }
  DisplayCoverage c;
  c.display = d.id;
  c.pixels = 1LL * d.width * d.height;
  int bx0 = d.width, by0 = d.height, bx1 = 0, by1 = 0;
  for (std::size_t j = 0; j + 1 < ny; ++j) {
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      int& n = count[j * nx + i];
      if (i > 0) n += count[j * nx + i - 1];
      if (j > 0) n += count[(j - 1) * nx + i];
      if (i > 0 && j > 0) n -= count[(j - 1) * nx + i - 1];
      const long long area = 1LL * (xs[i + 1] - xs[i]) * (ys[j + 1] - ys[j]);
      if (n >= 1) c.covered += area;
      if (n >= 2) c.overlapped += area;
      if (n == 0) {
        bx0 = std::min(bx0, xs[i]);
        by0 = std::min(by0, ys[j]);
        bx1 = std::max(bx1, xs[i + 1]);
        by1 = std::max(by1, ys[j + 1]);
      }
    }
  }
  if (bx1 > bx0) c.uncovered_box = {bx0, by0, bx1 - bx0, by1 - by0};
  return c;
}

}  // namespace

std::vector<DisplayCoverage> display_coverage(const Wall& wall,
                                              const std::vector<DisplayTile>& tiles) {
  std::vector<DisplayCoverage> out;
  for (const Display& d : wall.displays) {
    std::vector<const Rect*> rects;
    for (const DisplayTile& t : tiles) {
      if (t.display == d.id) rects.push_back(&t.on_display);
    }
    out.push_back(cover_one(d, rects));
  }
  return out;
}

std::vector<std::string> coverage_warnings(const Wall& wall,
                                           const std::vector<DisplayCoverage>& coverage) {
  std::vector<std::string> out;
  for (const DisplayCoverage& c : coverage) {
    if (c.covered == c.pixels) continue;
    const Display& d = wall.displays[c.display];
    const Rect& b = c.uncovered_box;
    out.push_back(
        fmt::format("canvas area {}x{} at {},{} (display {}: {} pixels) is not covered by any tile",
                    b.w, b.h, d.canvas_x + b.x, d.canvas_y + b.y, d.id, c.pixels - c.covered));
  }
  return out;
}

}  // namespace l2
