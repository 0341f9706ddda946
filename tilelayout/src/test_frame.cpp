#include "tilelayout/test_frame.hpp"

#include "tilelayout/test_pattern.hpp"

namespace l2 {

void fill_test_pattern(const ServerPlan& plan, RgbImage& fb) {
  for (const PackedTile& p : plan.tiles) {
    const Rect& d = p.tile.on_display;
    for (int j = 0; j < d.h; ++j) {
      std::uint8_t* px = fb.row(p.fb_y + j).data() + static_cast<std::size_t>(p.fb_x) * 3;
      for (int i = 0; i < d.w; ++i, px += 3) {
        const Rgb c = test_pattern(p.tile.display, d.x + i, d.y + j);
        px[0] = c.r;
        px[1] = c.g;
        px[2] = c.b;
      }
    }
  }
}

RgbImage test_frame(const ServerPlan& plan, bool frame_parity) {
  RgbImage fb(plan.fb_width, plan.fb_height);
  fill_test_pattern(plan, fb);
  draw_headers(plan, frame_parity, fb);
  return fb;
}

}  // namespace l2
