#include "displays/wall_view.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace l2 {

namespace {

// Edges are scaled, not sizes, so neighbouring displays keep their mullion and never overlap.
int scaled(int v, double scale) {
  return static_cast<int>(std::lround(v * scale));
}

}  // namespace

Rect wall_extent(const Wall& wall) {
  if (wall.displays.empty()) return {};
  int x0 = wall.displays[0].canvas_x, y0 = wall.displays[0].canvas_y;
  int x1 = x0, y1 = y0;
  for (const Display& d : wall.displays) {
    x0 = std::min(x0, d.canvas_x);
    y0 = std::min(y0, d.canvas_y);
    x1 = std::max(x1, d.on_canvas().right());
    y1 = std::max(y1, d.on_canvas().bottom());
  }
  return {x0, y0, x1 - x0, y1 - y0};
}

WallView fit_wall(const Wall& wall, int max_width, int max_height, int overlay_height) {
  const Rect extent = wall_extent(wall);
  if (extent.empty()) throw std::invalid_argument("the wall has no displays to show");
  const int room_height = max_height - overlay_height;
  if (max_width <= 0 || room_height <= 0) {
    throw std::invalid_argument("no room to show the wall in the window");
  }
  WallView view;
  view.scale = std::min({1.0, static_cast<double>(max_width) / extent.w,
                         static_cast<double>(room_height) / extent.h});
  for (const Display& d : wall.displays) {
    const int x0 = scaled(d.canvas_x - extent.x, view.scale);
    const int y0 = scaled(d.canvas_y - extent.y, view.scale);
    const int x1 = scaled(d.on_canvas().right() - extent.x, view.scale);
    const int y1 = scaled(d.on_canvas().bottom() - extent.y, view.scale);
    view.display_rects.push_back({x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0)});
  }
  const int wall_height = std::max(1, scaled(extent.h, view.scale));
  view.width = std::max(1, scaled(extent.w, view.scale));
  view.overlay = {0, wall_height, view.width, overlay_height};
  view.height = wall_height + overlay_height;
  return view;
}

Rect fit_display(int display_width, int display_height, int width, int height) {
  if (display_width <= 0 || display_height <= 0 || width <= 0 || height <= 0) return {};
  const double scale = std::min({1.0, static_cast<double>(width) / display_width,
                                 static_cast<double>(height) / display_height});
  const int w = std::max(1, scaled(display_width, scale));
  const int h = std::max(1, scaled(display_height, scale));
  return {(width - w) / 2, (height - h) / 2, w, h};
}

}  // namespace l2
