#include "draw_rgb.hpp"

#include <cstring>
#include <vector>

#include "pipeserver/gl_api.hpp"

namespace l2::detail {

void draw_rgb(const RgbImage& rgb, int gl_x, int gl_y) {
  // GL takes rows bottom to top. glDrawPixels with no zoom and no pixel transfer writes the
  // bytes unchanged (dithering is off: tile_renderer.cpp).
  std::vector<std::uint8_t> bottom_up(rgb.bytes().size());
  for (int y = 0; y < rgb.height(); ++y) {
    std::memcpy(bottom_up.data() + static_cast<std::size_t>(rgb.height() - 1 - y) * rgb.stride(),
                rgb.row(y).data(), rgb.stride());
  }
  gl().PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl().WindowPos2i(gl_x, gl_y);
  gl().DrawPixels(rgb.width(), rgb.height(), GL_RGB, GL_UNSIGNED_BYTE, bottom_up.data());
}

}  // namespace l2::detail
