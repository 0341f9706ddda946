// Spec §4 rule 3: the headers of every packed row, scanline by scanline.
#include "image/rgb_image.hpp"
#include "strip_headers/strip_header.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

void put(RgbImage& fb, int x, int y, const StripHeader& h) {
  write_header_pixels(encode(h), fb.row(y).data() + static_cast<std::size_t>(x) * 3, 3);
}

}  // namespace

void draw_headers(const ServerPlan& plan, bool frame_parity, RgbImage& fb) {
  if (fb.width() != plan.fb_width || fb.height() != plan.fb_height) {
    throw LayoutError("draw_headers: framebuffer size does not match the plan");
  }
  for (const PackedRow& row : plan.rows) {
    const PackedTile* first = plan.tiles.data() + row.first_tile;
    const PackedTile* last = first + row.tile_count - 1;
    const int end_x = last->fb_x + last->tile.on_display.w;
    for (int r = 0; r < row.height; ++r) {
      const int y = row.y + r;
      for (const PackedTile* p = first; p <= last; ++p) {
        const Rect& d = p->tile.on_display;
        put(fb, p->fb_x - kHeaderPixels, y,
            r < d.h ? StripHeader::copy(frame_parity, p->tile.display, d.x, d.y + r, d.w)
                    : StripHeader::skip(frame_parity, d.w));
      }
      if (plan.fb_width - end_x >= kHeaderPixels) put(fb, end_x, y, StripHeader::end());
    }
  }
}

}  // namespace l2

namespace l2 {

void clear_outside_tiles(const ServerPlan& plan, RgbImage& fb) {
  if (fb.width() != plan.fb_width || fb.height() != plan.fb_height) {
    throw LayoutError("clear_outside_tiles: framebuffer size does not match the plan");
  }
  for (const PackedRow& row : plan.rows) {
    const PackedTile* first = plan.tiles.data() + row.first_tile;
    const PackedTile* last = first + row.tile_count - 1;
    const int end_x = last->fb_x + last->tile.on_display.w;
    fb.fill_rect(end_x, row.y, plan.fb_width - end_x, row.height, {});
    for (const PackedTile* p = first; p <= last; ++p) {
      const Rect& d = p->tile.on_display;
      fb.fill_rect(p->fb_x, row.y + d.h, d.w, row.height - d.h, {});
    }
  }
  const int below = plan.used_height();
  fb.fill_rect(0, below, plan.fb_width, plan.fb_height - below, {});
}

}  // namespace l2
