#include "pipeserver/depth_out.hpp"

#include <GL/gl.h>

#include <vector>

#include "pipeserver/scan_out.hpp"

namespace l2 {
namespace {

void copy_depth(const PackedTile& p, const TileInWindow& from, std::uint32_t far_as,
                std::uint8_t* frame, std::size_t row_bytes) {
  const int w = p.tile.on_display.w, h = p.tile.on_display.h;
  std::vector<std::uint32_t> depth(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  // As 32-bit integers a 24-bit depth buffer reads back as its value in the top 24 bits.
  glReadPixels(from.x, from.window.height() - from.y - h, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
               depth.data());
  for (int r = 0; r < h; ++r) {
    // GL rows go bottom to top; the tile's top scanline is its last GL row.
    const std::uint32_t* src = depth.data() + static_cast<std::size_t>(h - 1 - r) * w;
    std::uint8_t* dst = frame + static_cast<std::size_t>(p.fb_y + r) * row_bytes +
                        static_cast<std::size_t>(p.fb_x + w) * 3;
    for (int i = 0; i < w; ++i, dst += 3) {
      std::uint32_t d = src[i] >> 8;
      if (d == kFarDepth) d = far_as;
      dst[0] = static_cast<std::uint8_t>(d >> 16);
      dst[1] = static_cast<std::uint8_t>(d >> 8);
      dst[2] = static_cast<std::uint8_t>(d);
    }
  }
}

}  // namespace

void copy_tile_out(const PackedTile& p, const TileInWindow& from, std::uint32_t far_as,
                   std::span<std::uint8_t> frame, int fb_width) {
  const std::size_t row_bytes = static_cast<std::size_t>(fb_width) * 3;
  const int w = p.tile.on_display.w, h = p.tile.on_display.h;
  const std::size_t window_row = static_cast<std::size_t>(from.window.width()) * 4;
  for (int r = 0; r < h; ++r) {
    const std::size_t gl_row = static_cast<std::size_t>(from.window.height() - 1 - from.y - r);
    rgba_to_rgb_row(from.window.rgba() + gl_row * window_row + static_cast<std::size_t>(from.x) * 4,
                    frame.data() + static_cast<std::size_t>(p.fb_y + r) * row_bytes +
                        static_cast<std::size_t>(p.fb_x) * 3,
                    w);
  }
  if (p.tile.compositing == Compositing::Depth)
    copy_depth(p, from, far_as, frame.data(), row_bytes);
}

}  // namespace l2
