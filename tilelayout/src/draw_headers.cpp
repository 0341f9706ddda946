// Spec §4 rule 3 over a whole framebuffer: the headers of every scanline, drawn from the one
// encoding FrameHeaders makes (the scan-out draws the same ones row by row).
#include "image/rgb_image.hpp"
#include "strip_headers/strip_header.hpp"
#include "tilelayout/frame_headers.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

void draw_headers(const PipeserverPlan& plan, bool frame_parity, RgbImage& fb) {
  if (fb.width() != plan.fb_width || fb.height() != plan.fb_height) {
    throw LayoutError("draw_headers: framebuffer size does not match the plan");
  }
  const FrameHeaders headers(plan, frame_parity);
  for (int y = 0; y < fb.height(); ++y) headers.draw_row(y, fb.row(y));
}

void clear_outside_tiles(const PipeserverPlan& plan, RgbImage& fb) {
  if (fb.width() != plan.fb_width || fb.height() != plan.fb_height) {
    throw LayoutError("clear_outside_tiles: framebuffer size does not match the plan");
  }
  for (const PackedRow& row : plan.rows) {
    const PackedTile* first = plan.tiles.data() + row.first_tile;
    const PackedTile* last = first + row.tile_count - 1;
    const int end_x = last->fb_x + payload_columns(last->tile);
    fb.fill_rect(end_x, row.y, plan.fb_width - end_x, row.height, {});
    for (const PackedTile* p = first; p <= last; ++p) {
      // Below a shorter tile only the SKIP header stays: an extension word's columns too are
      // pixels the SKIP passes over.
      const int from = p->fb_x - gap_columns(p->tile) + kHeaderPixels;
      const int h = p->tile.on_display.h;
      fb.fill_rect(from, row.y + h, p->fb_x + payload_columns(p->tile) - from, row.height - h, {});
    }
  }
  const int below = plan.used_height();
  fb.fill_rect(0, below, plan.fb_width, plan.fb_height - below, {});
}

}  // namespace l2
