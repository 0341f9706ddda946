// Spec §4 rule 3: while a packed row lasts, each tile's gap holds COPY (or EXT and its
// extension word, §7) for the tile's scanlines and SKIP below a shorter tile; the stamp strip's
// SKIP follows in its row (tile_layout.hpp); an END follows the row's last tile when two pixels
// are left.
#include "tilelayout/frame_headers.hpp"

#include <fmt/format.h>

#include <cstring>
#include <stdexcept>

#include "strip_headers/extension_word.hpp"
#include "strip_headers/strip_header.hpp"

namespace l2 {
namespace {

// The headers of one tile on scanline r of its row: COPY, or EXT and its extension word, while
// the tile lasts; below it a SKIP over the rest of its gap and its payload, so that the next
// header lands where it does on the tile's own scanlines.
template <class Put>
void put_tile(const PackedTile& p, int r, bool frame_parity, Put& put) {
  const DisplayTile& t = p.tile;
  const Rect& d = t.on_display;
  const int gap_x = p.fb_x - gap_columns(t);
  if (r >= d.h) {
    put(gap_x, encode(StripHeader::skip(frame_parity,
                                        gap_columns(t) - kHeaderPixels + payload_columns(t))));
    return;
  }
  StripHeader h = StripHeader::copy(frame_parity, header_id(t), d.x, d.y + r, d.w);
  if (t.compositing == Compositing::Copy) return put(gap_x, encode(h));
  h.op = StripOp::Ext;
  put(gap_x, encode(h));
  put(gap_x + kHeaderPixels, encode(t.compositing == Compositing::Key ? Extension::key_colour(t.key)
                                                                      : Extension::depth()));
}

}  // namespace

FrameHeaders::FrameHeaders(const PipeserverPlan& plan, bool frame_parity)
    : width_(plan.fb_width), height_(plan.fb_height) {
  row_begin_.reserve(static_cast<std::size_t>(height_) + 1);
  auto next_scanline = [&] { row_begin_.push_back(static_cast<std::uint32_t>(headers_.size())); };
  auto put = [&](int x, std::uint64_t value) {
    Placed p{static_cast<std::uint32_t>(x) * 3, {}};
    write_header_pixels(value, p.pixels.data(), 3);
    headers_.push_back(p);
  };
  for (int i = 0; i < static_cast<int>(plan.rows.size()); ++i) {
    const PackedRow& row = plan.rows[static_cast<std::size_t>(i)];
    while (static_cast<int>(row_begin_.size()) < row.y) next_scanline();
    const PackedTile* first = plan.tiles.data() + row.first_tile;
    const PackedTile* last = first + row.tile_count - 1;
    int end_x = last->fb_x + payload_columns(last->tile);
    // The stamp strip: a tile of height zero, so a SKIP over its one pixel on every scanline.
    const bool stamp = i == plan.stamp_row;
    if (stamp) end_x += kStampStripColumns;
    for (int r = 0; r < row.height; ++r) {
      next_scanline();
      for (const PackedTile* p = first; p <= last; ++p) put_tile(*p, r, frame_parity, put);
      if (stamp) put(plan.stamp_x - kHeaderPixels, encode(StripHeader::skip(frame_parity, 1)));
      if (plan.fb_width - end_x >= kHeaderPixels) put(end_x, encode(StripHeader::end()));
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
