#include "pipeserver/depth_out.hpp"

#include <cstring>
#include <vector>

#include "pipeserver/gl_api.hpp"
#include "pipeserver/scan_out.hpp"

namespace l2 {
namespace {

// Where tile pixel (0, r) of a turned tile reads in a buffer of `stride` elements a row with GL's
// bottom-up rows, `bottom` the index of the tile's on_canvas top row; and how far the next tile
// pixel of the row is, in elements (tile_map: u along x, v down the canvas).
struct TurnedRow {
  std::ptrdiff_t start = 0, step = 0;
};
TurnedRow turned_row(const PanelMap& m, int r, int left, int top_row, std::ptrdiff_t stride) {
  return {static_cast<std::ptrdiff_t>(top_row - m.v(0, r)) * stride + left + m.u(0, r),
          static_cast<std::ptrdiff_t>(m.ux) - static_cast<std::ptrdiff_t>(m.vx) * stride};
}

void put_depth(std::uint32_t raw, std::uint32_t far_as, std::uint8_t* dst) {
  std::uint32_t d = raw >> 8;
  if (d == kFarDepth) d = far_as;
  dst[0] = static_cast<std::uint8_t>(d >> 16);
  dst[1] = static_cast<std::uint8_t>(d >> 8);
  dst[2] = static_cast<std::uint8_t>(d);
}

void copy_depth(const PackedTile& p, const TileInWindow& from, std::uint32_t far_as,
                std::uint8_t* frame, std::size_t row_bytes) {
  const Rect& c = p.tile.on_canvas;  // read upright, as rendered
  const int w = p.tile.on_display.w, h = p.tile.on_display.h;
  std::vector<std::uint32_t> depth(static_cast<std::size_t>(c.w) * static_cast<std::size_t>(c.h));
  gl().PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl().PixelStorei(GL_PACK_ROW_LENGTH, 0);
  // As 32-bit integers a 24-bit depth buffer reads back as its value in the top 24 bits.
  gl().ReadPixels(from.x, from.window.height() - from.y - c.h, c.w, c.h, GL_DEPTH_COMPONENT,
                  GL_UNSIGNED_INT, depth.data());
  const PanelMap m = tile_map(p.tile);
  for (int r = 0; r < h; ++r) {
    // GL rows go bottom to top; the tile's top canvas row is its last GL row.
    const TurnedRow at = turned_row(m, r, 0, c.h - 1, c.w);
    const std::uint32_t* src = depth.data() + at.start;
    std::uint8_t* dst = frame + static_cast<std::size_t>(p.fb_y + r) * row_bytes +
                        static_cast<std::size_t>(p.fb_x + w) * 3;
    for (int i = 0; i < w; ++i, dst += 3, src += at.step) put_depth(*src, far_as, dst);
  }
}

// A tile of a turned display: each of its rows is a column (or a reversed row) of the window.
void copy_turned(const PackedTile& p, const TileInWindow& from, std::uint8_t* frame,
                 std::size_t row_bytes) {
  const PanelMap m = tile_map(p.tile);
  const int w = p.tile.on_display.w;
  for (int r = 0; r < p.tile.on_display.h; ++r) {
    const TurnedRow at =
        turned_row(m, r, from.x, from.window.height() - 1 - from.y, from.window.width());
    const std::uint8_t* src = from.window.rgba() + at.start * 4;
    std::uint8_t* dst = frame + static_cast<std::size_t>(p.fb_y + r) * row_bytes +
                        static_cast<std::size_t>(p.fb_x) * 3;
    for (int i = 0; i < w; ++i, dst += 3, src += at.step * 4) std::memcpy(dst, src, 3);
  }
}

}  // namespace

void copy_tile_out(const PackedTile& p, const TileInWindow& from, std::uint32_t far_as,
                   std::span<std::uint8_t> frame, int fb_width) {
  const std::size_t row_bytes = static_cast<std::size_t>(fb_width) * 3;
  const int w = p.tile.on_display.w, h = p.tile.on_display.h;
  const std::size_t window_row = static_cast<std::size_t>(from.window.width()) * 4;
  if (!p.tile.orientation.identity()) {
    copy_turned(p, from, frame.data(), row_bytes);
  } else {
    for (int r = 0; r < h; ++r) {
      const std::size_t gl_row = static_cast<std::size_t>(from.window.height() - 1 - from.y - r);
      rgba_to_rgb_row(
          from.window.rgba() + gl_row * window_row + static_cast<std::size_t>(from.x) * 4,
          frame.data() + static_cast<std::size_t>(p.fb_y + r) * row_bytes +
              static_cast<std::size_t>(p.fb_x) * 3,
          w);
    }
  }
  if (p.tile.compositing == Compositing::Depth)
    copy_depth(p, from, far_as, frame.data(), row_bytes);
}

void sparse_depth_rows(const PipeserverPlan& plan, bool frame_parity, const DepthSkip& skip,
                       std::span<std::uint8_t> frame, SparseScratch& scratch) {
  const std::size_t row_bytes = static_cast<std::size_t>(plan.fb_width) * 3;
  for (const PackedTile& p : plan.tiles) {
    if (p.tile.compositing != Compositing::Depth) continue;
    const Rect& d = p.tile.on_display;
    StripHeader dense = StripHeader::copy(frame_parity, p.tile.display, d.x, d.y, d.w);
    dense.op = StripOp::Ext;
    // Without a stamp strip the frame number marks the first tile's first pixel, which the run
    // reads back there (live_mode.cpp): that scanline stays dense.
    const int first_row = &p == plan.tiles.data() && !plan.has_stamp_strip() ? 1 : 0;
    for (int r = first_row; r < d.h; ++r) {
      std::uint8_t* colour = frame.data() + static_cast<std::size_t>(p.fb_y + r) * row_bytes +
                             static_cast<std::size_t>(p.fb_x) * 3;
      find_depth_spans(colour, colour + static_cast<std::size_t>(d.w) * 3, d.w, skip,
                       scratch.spans);
      dense.y = static_cast<std::uint16_t>(d.y + r);
      pack_sparse_row(colour - static_cast<std::size_t>(gap_columns(p.tile)) * 3, dense,
                      scratch.spans, scratch.row);
    }
  }
}

}  // namespace l2
