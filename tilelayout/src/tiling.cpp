// Cutting the canvas into logical tiles, and logical tiles into display tiles.
#include <fmt/format.h>

#include "cost_map.hpp"
#include "tilelayout/planner.hpp"

namespace l2 {
namespace {

std::vector<Rect> grid_tiles(const Wall& w) {
  std::vector<Rect> out;
  const int tw = w.tiling.tile_width, th = w.tiling.tile_height;
  for (int y = 0; y < w.canvas_height; y += th) {
    for (int x = 0; x < w.canvas_width; x += tw) {
      out.push_back(intersect({x, y, tw, th}, {0, 0, w.canvas_width, w.canvas_height}));
    }
  }
  return out;
}

std::vector<Rect> strip_tiles(const Wall& w) {
  std::vector<Rect> out;
  const long long s = w.tiling.strip_count, t = w.tiling.substrip_count;
  for (long long i = 0; i < s; ++i) {
    const int y0 = static_cast<int>(w.canvas_height * i / s);
    const int y1 = static_cast<int>(w.canvas_height * (i + 1) / s);
    for (long long j = 0; j < t; ++j) {
      const int x0 = static_cast<int>(w.canvas_width * j / t);
      const int x1 = static_cast<int>(w.canvas_width * (j + 1) / t);
      out.push_back({x0, y0, x1 - x0, y1 - y0});
    }
  }
  return out;
}

// Median cut: each rectangle holding n tiles is cut across its longer side where the cost on
// the first side is n1/n of the whole (n1 = n/2), each side keeping at least one pixel per tile.
class KdSplitter {
 public:
  explicit KdSplitter(const Wall& w) : wall_(w), costs_(w) {}

  void split(const Rect& r, int n, std::vector<Rect>& out) const {
    if (n == 1) {
      out.push_back(r);
      return;
    }
    const int n1 = n / 2, n2 = n - n1;
    const bool vertical_first = r.w >= r.h;
    for (bool vertical : {vertical_first, !vertical_first}) {
      const int across = vertical ? r.h : r.w, along = vertical ? r.w : r.h;
      const int lo = (n1 + across - 1) / across, hi = along - (n2 + across - 1) / across;
      if (lo > hi) continue;
      const int cut = best_cut(r, vertical, lo, hi, double(n1) / n);
      const Rect a = vertical ? Rect{r.x, r.y, cut, r.h} : Rect{r.x, r.y, r.w, cut};
      const Rect b =
          vertical ? Rect{r.x + cut, r.y, r.w - cut, r.h} : Rect{r.x, r.y + cut, r.w, r.h - cut};
      split(a, n1, out);
      split(b, n2, out);
      return;
    }
    throw LayoutError(
        fmt::format("{}:{}: tiling.tile_count: cannot cut {} tiles out of {}x{} "
                    "at {},{}",
                    wall_.source.string(), wall_.tiling_line, n, r.w, r.h, r.x, r.y));
  }

 private:
  // The cut offset in lo..hi whose first part is closest to `fraction` of the cost. Rectangles
  // nobody sees (cost 0) are cut by area instead.
  int best_cut(const Rect& r, bool vertical, int lo, int hi, double fraction) const {
    const double total = costs_.cost(r);
    const auto first = [&](int cut) {
      const Rect a = vertical ? Rect{r.x, r.y, cut, r.h} : Rect{r.x, r.y, r.w, cut};
      return total > 0 ? costs_.cost(a) : double(a.area());
    };
    const double target = (total > 0 ? total : double(r.area())) * fraction;
    int a = lo, b = hi;  // smallest cut with first(cut) >= target, by bisection
    while (a < b) {
      const int mid = a + (b - a) / 2;
      if (first(mid) >= target)
        b = mid;
      else
        a = mid + 1;
    }
    if (a > lo && target - first(a - 1) < first(a) - target) return a - 1;
    return a;
  }

  const Wall& wall_;
  CostMap costs_;
};

}  // namespace

std::vector<Rect> make_logical_tiles(const Wall& wall) {
  switch (wall.tiling.kind) {
    case TilingKind::Grid:
      return grid_tiles(wall);
    case TilingKind::List:
      return wall.tiling.rects;
    case TilingKind::Strips:
      return strip_tiles(wall);
    case TilingKind::KdSplit:
      break;
  }
  std::vector<Rect> out;
  KdSplitter(wall).split({0, 0, wall.canvas_width, wall.canvas_height}, wall.tiling.tile_count,
                         out);
  return out;
}

std::vector<DisplayTile> split_at_displays(const Wall& wall, const std::vector<Rect>& logical) {
  // Each display's parts: its rectangle, or a packed stereo display's halves, which different
  // eyes draw, so that no tile spans both.
  std::vector<std::vector<DisplayPart>> parts;
  for (const Display& d : wall.displays) parts.push_back(display_parts(wall.stereo, d));
  std::vector<DisplayTile> out;
  for (int i = 0; i < static_cast<int>(logical.size()); ++i) {
    for (std::size_t k = 0; k < wall.displays.size(); ++k) {
      const Display& d = wall.displays[k];
      for (const DisplayPart& p : parts[k]) {
        const Rect part = intersect(logical[i], p.on_canvas);
        if (!part.empty())
          out.push_back({d.id, d.to_panel(part), part, i, Compositing::Copy, 0, d.orientation});
      }
    }
  }
  return out;
}

}  // namespace l2
