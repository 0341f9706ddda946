#include "tilelayout/test_frame.hpp"

#include "tilelayout/test_pattern.hpp"

namespace l2 {

namespace {

void put(std::uint8_t* px, Rgb c) {
  px[0] = c.r;
  px[1] = c.g;
  px[2] = c.b;
}

Rgb depth_pixel(std::uint32_t depth) {
  return {static_cast<std::uint8_t>(depth >> 16), static_cast<std::uint8_t>(depth >> 8 & 0xFF),
          static_cast<std::uint8_t>(depth & 0xFF)};
}

// What tile `p` of a pipeserver rendering `layer` of `layers` sends for its pixel (x, y): its
// colour, and for DEPTH its depth pixel (test_pattern.hpp).
void fill_tile(const PackedTile& p, int layer, int layers, PatternPlace place, RgbImage& fb) {
  const DisplayTile& t = p.tile;
  const Rect& d = t.on_display;
  // On the canvas, a turned display's tile pixel (i, j) is where its tile map says.
  const bool canvas = place == PatternPlace::Canvas;
  const PanelMap m = canvas ? tile_map(t) : PanelMap{};
  const Rect& at = canvas ? t.on_canvas : t.on_display;
  const Rgb key{static_cast<std::uint8_t>(t.key >> 16), static_cast<std::uint8_t>(t.key >> 8),
                static_cast<std::uint8_t>(t.key)};
  for (int j = 0; j < d.h; ++j) {
    std::uint8_t* px = fb.row(p.fb_y + j).data() + static_cast<std::size_t>(p.fb_x) * 3;
    std::uint8_t* depth = px + static_cast<std::size_t>(d.w) * 3;
    for (int i = 0; i < d.w; ++i, px += 3, depth += 3) {
      const int x = at.x + m.u(i, j), y = at.y + m.v(i, j);
      if (t.compositing == Compositing::Depth) {
        const LayerPixel l = depth_test_pixel(t.display, x, y, layer, layers);
        put(px, l.colour);
        put(depth, depth_pixel(l.depth));
      } else if (t.compositing == Compositing::Key && key_test_transparent(x, y)) {
        put(px, key);
      } else {
        put(px, test_pattern(t.display, x, y));
      }
    }
  }
}

}  // namespace

void fill_test_pattern(const PipeserverPlan& plan, RgbImage& fb, PatternPlace place) {
  for (const PackedTile& p : plan.tiles) fill_tile(p, plan.layer, plan.layers, place, fb);
}

RgbImage test_frame(const PipeserverPlan& plan, bool frame_parity, PatternPlace place) {
  RgbImage fb(plan.fb_width, plan.fb_height);
  fill_test_pattern(plan, fb, place);
  draw_headers(plan, frame_parity, fb);
  return fb;
}

}  // namespace l2
