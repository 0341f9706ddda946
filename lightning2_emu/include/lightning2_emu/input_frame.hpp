// One scanned-out frame on an input, as the router reads it: a view, never a copy, so the
// router can read straight out of a capture buffer or shared memory.
#pragma once

#include <cstddef>
#include <cstdint>

#include "image/rgb_image.hpp"

namespace l2 {

struct InputFrame {
  const std::uint8_t* data = nullptr;  // row 0 (top scanline); nullptr: no signal this frame
  std::ptrdiff_t stride = 0;           // bytes from one row to the next
  int width = 0, height = 0;
  int bytes_per_pixel = 3;  // 3 = RGB, 4 = RGBA (A is dropped, as on the link)

  bool present() const { return data != nullptr && width > 0 && height > 0; }
  const std::uint8_t* row(int y) const { return data + stride * y; }

  static InputFrame of(const RgbImage& image) {
    return {image.data(), static_cast<std::ptrdiff_t>(image.stride()), image.width(),
            image.height(), RgbImage::kChannels};
  }
};

}  // namespace l2
