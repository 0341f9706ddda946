#include "strip_headers/strip_header.hpp"

#include <fmt/format.h>
#include <stdexcept>

namespace l2 {
namespace {

using namespace header_bits;

void require_field(const char* name, int value, int max) {
  if (value < 0 || value > max) {
    throw std::out_of_range(
        fmt::format("strip header field '{}' = {} is outside 0..{}", name, value, max));
  }
}

}  // namespace

StripHeader StripHeader::copy(bool frame, int display, int x, int y, int width) {
  require_field("display", display, kMaxDisplays - 1);
  require_field("x", x, kMaxCoordinate);
  require_field("y", y, kMaxCoordinate);
  require_field("width", width, kMaxCoordinate);
  return {StripOp::Copy,
          frame,
          static_cast<std::uint8_t>(display),
          static_cast<std::uint16_t>(x),
          static_cast<std::uint16_t>(y),
          static_cast<std::uint16_t>(width)};
}

StripHeader StripHeader::skip(bool frame, int width) {
  require_field("width", width, kMaxCoordinate);
  return {StripOp::Skip, frame, 0, 0, 0, static_cast<std::uint16_t>(width)};
}

std::uint64_t encode(const StripHeader& h) {
  require_field("display", h.display, kMaxDisplays - 1);
  require_field("x", h.x, kMaxCoordinate);
  require_field("y", h.y, kMaxCoordinate);
  require_field("width", h.width, kMaxCoordinate);
  const std::uint64_t message = std::uint64_t{static_cast<std::uint8_t>(h.op)} << kOpShift |
                                std::uint64_t{h.frame} << kFrameShift |
                                std::uint64_t{h.display} << kDisplayShift |
                                std::uint64_t{h.x} << kXShift | std::uint64_t{h.y} << kYShift |
                                std::uint64_t{h.width} << kWidthShift;
  return message | crc3(message >> 3);
}

void write_header_pixels(std::uint64_t value, std::uint8_t* p, int bytes_per_pixel) {
  for (int i = 0; i < 6; ++i) {
    const int pixel = i / 3;
    p[pixel * bytes_per_pixel + i % 3] = static_cast<std::uint8_t>(value >> (40 - 8 * i));
  }
  if (bytes_per_pixel == 4) {
    p[3] = 255;
    p[7] = 255;
  }
}

const char* to_string(StripOp op) {
  switch (op) {
    case StripOp::End:
      return "END";
    case StripOp::Copy:
      return "COPY";
    case StripOp::Skip:
      return "SKIP";
    case StripOp::Ext:
      return "EXT";
  }
  return "?";
}

std::string to_string(const StripHeader& h) {
  return fmt::format("{} f={} d={} x={} y={} w={}", to_string(h.op), h.frame ? 1 : 0,
                     int{h.display}, h.x, h.y, h.width);
}

}  // namespace l2
