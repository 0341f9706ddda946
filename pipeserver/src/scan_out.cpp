#include "pipeserver/scan_out.hpp"

#include <fmt/format.h>

#include <cstring>
#include <stdexcept>

namespace l2 {

namespace {

// Four pixels at a time: read 16 bytes, write 12. Written with fixed-size memcpy so the compiler
// turns it into plain loads and stores, whatever the alignment.
void rgba_row_to_rgb(const std::uint8_t* src, std::uint8_t* dst, int width) {
  int x = 0;
  for (; x + 4 <= width; x += 4, src += 16, dst += 12) {
    std::uint8_t tmp[16];
    std::memcpy(tmp, src, 16);
    dst[0] = tmp[0], dst[1] = tmp[1], dst[2] = tmp[2];
    dst[3] = tmp[4], dst[4] = tmp[5], dst[5] = tmp[6];
    dst[6] = tmp[8], dst[7] = tmp[9], dst[8] = tmp[10];
    dst[9] = tmp[12], dst[10] = tmp[13], dst[11] = tmp[14];
  }
  for (; x < width; ++x, src += 4, dst += 3) {
    dst[0] = src[0], dst[1] = src[1], dst[2] = src[2];
  }
}

}  // namespace

void scan_out(const std::uint8_t* rgba, int width, int height, std::span<std::uint8_t> dst_rgb) {
  if (width < 0 || height < 0) throw std::invalid_argument("scan_out: negative size");
  const std::size_t w = static_cast<std::size_t>(width);
  const std::size_t need = w * static_cast<std::size_t>(height) * 3;
  if (dst_rgb.size() < need) {
    throw std::invalid_argument(
        fmt::format("scan_out: destination holds {} bytes, {}x{} RGB needs {}", dst_rgb.size(),
                    width, height, need));
  }
  for (int y = 0; y < height; ++y) {
    // GL row 0 is the bottom scanline; scan-out row 0 is the top.
    const std::uint8_t* src = rgba + static_cast<std::size_t>(height - 1 - y) * w * 4;
    rgba_row_to_rgb(src, dst_rgb.data() + static_cast<std::size_t>(y) * w * 3, width);
  }
}

}  // namespace l2
