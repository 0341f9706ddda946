#include "tilelayout/pictures.hpp"

#include <algorithm>
#include <cmath>

#include "digit_font.hpp"

namespace l2 {
namespace {

constexpr Rgb kUnused{40, 40, 40};
constexpr Rgb kGap{255, 255, 255};
constexpr Rgb kOutline{20, 20, 20};
constexpr Rgb kLabel{0, 0, 0};

void outline(RgbImage& img, const Rect& r, Rgb c, int thickness) {
  img.fill_rect(r.x, r.y, r.w, thickness, c);
  img.fill_rect(r.x, r.bottom() - thickness, r.w, thickness, c);
  img.fill_rect(r.x, r.y, thickness, r.h, c);
  img.fill_rect(r.right() - thickness, r.y, thickness, r.h, c);
}

// A label centred in `r`, as large as fits a quarter of its height; none if it cannot fit.
void label(RgbImage& img, const Rect& r, int value) {
  int scale = std::max(1, std::min(r.h / 4 / 5, 12));
  while (scale > 1 && number_width(value, scale) > r.w - 4) --scale;
  const int w = number_width(value, scale), h = number_height(scale);
  if (w > r.w - 2 || h > r.h - 2) return;
  draw_number(img, r.x + (r.w - w) / 2, r.y + (r.h - h) / 2, value, scale, kLabel);
}

}  // namespace

Rgb palette_colour(int i) {
  // Hues spread by the golden angle, light enough for black labels to read on.
  const double h = std::fmod(i * 137.508, 360.0) / 60.0;
  const double x = 1 - std::abs(std::fmod(h, 2.0) - 1);
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0:
      r = 1, g = x;
      break;
    case 1:
      r = x, g = 1;
      break;
    case 2:
      g = 1, b = x;
      break;
    case 3:
      g = x, b = 1;
      break;
    case 4:
      r = x, b = 1;
      break;
    default:
      r = 1, b = x;
      break;
  }
  const auto channel = [](double v) { return static_cast<std::uint8_t>(110 + v * 145); };
  return {channel(r), channel(g), channel(b)};
}

RgbImage framebuffer_picture(const ServerPlan& plan) {
  RgbImage img(plan.fb_width, plan.fb_height, kUnused);
  for (const PackedRow& row : plan.rows) {
    for (int i = row.first_tile; i < row.first_tile + row.tile_count; ++i) {
      const int gap = gap_columns(plan.tiles[i].tile);
      img.fill_rect(plan.tiles[i].fb_x - gap, row.y, gap, row.height, kGap);
    }
  }
  for (const PackedTile& p : plan.tiles) {
    const Rect r{p.fb_x, p.fb_y, payload_columns(p.tile), p.tile.on_display.h};
    img.fill_rect(r.x, r.y, r.w, r.h, palette_colour(p.tile.display));
    if (r.w > 8 && r.h > 8) outline(img, r, kOutline, 1);
    label(img, r, p.tile.display);
  }
  return img;
}

RgbImage wall_picture(const TileLayout& layout) {
  const Wall& wall = layout.wall;
  // Large canvases are drawn smaller, by a whole factor, so the picture stays at most 4096
  // pixels on its longer side.
  const int scale = std::max(1, (std::max(wall.canvas_width, wall.canvas_height) + 4095) / 4096);
  const auto shrink = [scale](const Rect& r) {
    const int x0 = r.x / scale, y0 = r.y / scale;
    return Rect{x0, y0, (r.right() + scale - 1) / scale - x0,
                (r.bottom() + scale - 1) / scale - y0};
  };
  RgbImage img((wall.canvas_width + scale - 1) / scale, (wall.canvas_height + scale - 1) / scale,
               kUnused);
  for (std::size_t i = 0; i < layout.tiles.size(); ++i) {
    const Rect r = shrink(layout.tiles[i].on_canvas);
    img.fill_rect(r.x, r.y, r.w, r.h, palette_colour(layout.tile_server[i]));
  }
  for (std::size_t i = 0; i < layout.tiles.size(); ++i) {
    const Rect r = shrink(layout.tiles[i].on_canvas);
    if (r.w > 8 && r.h > 8) outline(img, r, kOutline, 1);
    label(img, r, layout.tile_server[i]);
  }
  for (const Display& d : wall.displays) outline(img, shrink(d.on_canvas()), {255, 255, 255}, 2);
  return img;
}

}  // namespace l2
