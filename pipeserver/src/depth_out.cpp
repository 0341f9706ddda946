#include "pipeserver/depth_out.hpp"

#include <GL/gl.h>
#include <fmt/format.h>

#include <stdexcept>

namespace l2 {

void scan_out_depth(const ServerPlan& plan, std::uint32_t far_as, std::span<std::uint8_t> frame) {
  const std::size_t row_bytes = static_cast<std::size_t>(plan.fb_width) * 3;
  if (frame.size() < row_bytes * static_cast<std::size_t>(plan.fb_height)) {
    throw std::invalid_argument(fmt::format("scan_out_depth: {} bytes for a {}x{} frame",
                                            frame.size(), plan.fb_width, plan.fb_height));
  }
  std::vector<std::uint32_t> depth;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  for (const PackedTile& p : plan.tiles) {
    if (p.tile.compositing != Compositing::Depth) continue;
    const int w = p.tile.on_display.w, h = p.tile.on_display.h;
    depth.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    // As 32-bit integers a 24-bit depth buffer reads back as its value in the top 24 bits.
    glReadPixels(p.fb_x, plan.fb_height - p.fb_y - h, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
                 depth.data());
    for (int r = 0; r < h; ++r) {
      // GL rows go bottom to top; the tile's top scanline is its last GL row.
      const std::uint32_t* src = depth.data() + static_cast<std::size_t>(h - 1 - r) * w;
      std::uint8_t* dst = frame.data() + static_cast<std::size_t>(p.fb_y + r) * row_bytes +
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
}

}  // namespace l2
