#include "tilelayout/coverage.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>

namespace l2 {
namespace {

// One display at a time, a byte per pixel counting the tiles on it (saturating at 2): memory
// and time bounded by the display size (at most 4095x4095), whatever the number of tiles.
DisplayCoverage cover_one(const Display& d, const std::vector<const Rect*>& rects) {
  std::vector<std::uint8_t> count(static_cast<std::size_t>(d.width) * d.height, 0);
  for (const Rect* r : rects) {
    const Rect c = intersect(*r, {0, 0, d.width, d.height});
    for (int y = c.y; y < c.bottom(); ++y) {
      std::uint8_t* row = count.data() + static_cast<std::size_t>(y) * d.width;
      for (int x = c.x; x < c.right(); ++x)
        row[x] = static_cast<std::uint8_t>(std::min(row[x] + 1, 2));
    }
  }
  DisplayCoverage out;
  out.display = d.id;
  out.pixels = 1LL * d.width * d.height;
  int bx0 = d.width, by0 = d.height, bx1 = 0, by1 = 0;
  for (int y = 0; y < d.height; ++y) {
    const std::uint8_t* row = count.data() + static_cast<std::size_t>(y) * d.width;
    for (int x = 0; x < d.width; ++x) {
      if (row[x] >= 1) ++out.covered;
      if (row[x] >= 2) ++out.overlapped;
      if (row[x] == 0) {
        bx0 = std::min(bx0, x);
        by0 = std::min(by0, y);
        bx1 = std::max(bx1, x + 1);
        by1 = std::max(by1, y + 1);
      }
    }
  }
  if (bx1 > bx0) out.uncovered_box = {bx0, by0, bx1 - bx0, by1 - by0};
  return out;
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
