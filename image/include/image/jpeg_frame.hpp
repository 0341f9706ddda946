// A JPEG frame sent over the network (a screen the control page shares, control_page/README.md):
// decoded from memory with libjpeg into an RgbImage, or refused in one line. Hostile bytes are
// expected: the header's declared size is checked against the limits and against what the
// bytes can hold (declared_size.hpp) before any pixel memory is taken, and a damaged or cut
// short stream is refused rather than shown half grey.
#pragma once

#include <cstddef>
#include <string_view>

#include "base/result.hpp"
#include "image/rgb_image.hpp"

namespace l2 {

struct JpegFrameLimits {
  int max_width = 3840, max_height = 2160;
  std::size_t max_bytes = std::size_t{16} << 20;
};

// The picture, or why not: "not a JPEG (it starts 89 50 4e 47)", "declares 65500x65500
// pixels, more than a shared frame may have (3840x2160)", "a damaged JPEG (Premature end of
// JPEG file)".
Result<RgbImage> decode_jpeg_frame(std::string_view bytes, const JpegFrameLimits& limits = {});

}  // namespace l2
