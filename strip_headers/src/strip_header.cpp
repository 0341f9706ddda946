#include "strip_headers/strip_header.hpp"

#include <fmt/format.h>
#include <stdexcept>

namespace l2 {
namespace {

constexpr int kOpShift = 46;
constexpr int kFrameShift = 45;
constexpr int kDisplayShift = 39;
constexpr int kXShift = 27;
constexpr int kYShift = 15;
constexpr int kWidthShift = 3;
constexpr std::uint64_t k12Bits = 0xFFF;
constexpr std::uint64_t kMask48 = (std::uint64_t{1} << 48) - 1;

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

namespace {

// The remainder is linear in the message, so it is the XOR of the remainders of each byte of
// M(x)·x^3 in its place: six 256-entry tables, built at compile time. This keeps decoding a
// header to a handful of loads, which matters because the router decodes one per strip.
constexpr std::uint8_t remainder_bitwise(std::uint64_t value48) {
  constexpr std::uint64_t kGenerator = 0b1011;  // x^3 + x + 1
  for (int bit = 47; bit >= 3; --bit) {
    if (value48 >> bit & 1) value48 ^= kGenerator << (bit - 3);
  }
  return static_cast<std::uint8_t>(value48 & 0b111);
}

struct Crc3Tables {
  std::uint8_t byte[6][256]{};
  constexpr Crc3Tables() {
    for (int i = 0; i < 6; ++i) {
      for (std::uint64_t b = 0; b < 256; ++b) byte[i][b] = remainder_bitwise(b << (8 * i));
    }
  }
};
constexpr Crc3Tables kCrc3;

}  // namespace

std::uint8_t crc3(std::uint64_t message45) {
  const std::uint64_t v = (message45 << 3) & kMask48;
  return kCrc3.byte[0][v & 0xFF] ^ kCrc3.byte[1][v >> 8 & 0xFF] ^ kCrc3.byte[2][v >> 16 & 0xFF] ^
         kCrc3.byte[3][v >> 24 & 0xFF] ^ kCrc3.byte[4][v >> 32 & 0xFF] ^
         kCrc3.byte[5][v >> 40 & 0xFF];
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

std::optional<StripHeader> decode(std::uint64_t value) {
  value &= kMask48;
  if (crc3(value >> 3) != (value & 0b111)) return std::nullopt;
  StripHeader h;
  h.op = static_cast<StripOp>(value >> kOpShift & 0b11);
  h.frame = (value >> kFrameShift & 1) != 0;
  h.display = static_cast<std::uint8_t>(value >> kDisplayShift & 0x3F);
  h.x = static_cast<std::uint16_t>(value >> kXShift & k12Bits);
  h.y = static_cast<std::uint16_t>(value >> kYShift & k12Bits);
  h.width = static_cast<std::uint16_t>(value >> kWidthShift & k12Bits);
  return h;
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
