// Spec §4 rule 3: while a packed row lasts, each tile's gap holds COPY for the tile's scanlines
// and SKIP below a shorter tile; an END follows the row's last tile when two pixels are left.
#include "tilelayout/frame_headers.hpp"

#include <fmt/format.h>

#include <cstring>
#include <stdexcept>

#include "strip_headers/strip_header.hpp"

namespace l2 {

FrameHeaders::FrameHeaders(const ServerPlan& plan, bool frame_parity)
    : width_(plan.fb_width), height_(plan.fb_height) {
  row_begin_.reserve(static_cast<std::size_t>(height_) + 1);
  auto next_scanline = [&] { row_begin_.push_back(static_cast<std::uint32_t>(headers_.size())); };
  auto put = [&](int x, const StripHeader& h) {
    Placed p{static_cast<std::uint32_t>(x) * 3, {}};
    write_header_pixels(encode(h), p.pixels.data(), 3);
    headers_.push_back(p);
  };
  for (const PackedRow& row : plan.rows) {
    while (static_cast<int>(row_begin_.size()) < row.y) next_scanline();
    const PackedTile* first = plan.tiles.data() + row.first_tile;
    const PackedTile* last = first + row.tile_count - 1;
    const int end_x = last->fb_x + last->tile.on_display.w;
    for (int r = 0; r < row.height; ++r) {
      next_scanline();
      for (const PackedTile* p = first; p <= last; ++p) {
        const Rect& d = p->tile.on_display;
        put(p->fb_x - kHeaderPixels,
            r < d.h ? StripHeader::copy(frame_parity, p->tile.display, d.x, d.y + r, d.w)
                    : StripHeader::skip(frame_parity, d.w));
      }
      if (plan.fb_width - end_x >= kHeaderPixels) put(end_x, StripHeader::end());
    }
  }
  while (static_cast<int>(row_begin_.size()) <= height_) next_scanline();  // and the end
}

void FrameHeaders::draw_row(int y, std::span<std::uint8_t> row) const {
  if (y < 0 || y >= height_ || row.size() < static_cast<std::size_t>(width_) * 3) {
    throw std::invalid_argument(
        fmt::format("FrameHeaders: scanline {} of {} bytes, the framebuffer is {}x{}", y,
                    row.size(), width_, height_));
  }
  const std::size_t y_index = static_cast<std::size_t>(y);
  for (std::uint32_t i = row_begin_[y_index]; i < row_begin_[y_index + 1]; ++i) {
    std::memcpy(row.data() + headers_[i].byte_offset, headers_[i].pixels.data(), 6);
  }
}

}  // namespace l2
