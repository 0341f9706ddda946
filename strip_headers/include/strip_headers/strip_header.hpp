// The 48-bit strip header of spec §2: the routing word a pipeserver draws into the two-pixel
// gap before every strip, and the emulator reads back out of the scanned-out frame.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace l2 {

enum class StripOp : std::uint8_t { End = 0, Copy = 1, Skip = 2, Ext = 3 };

// Field limits fixed by the bit widths of the header.
inline constexpr int kMaxDisplays = 64;      // display: 6 bits
inline constexpr int kMaxCoordinate = 4095;  // x, y, width: 12 bits
inline constexpr int kHeaderPixels = 2;      // a header spans two pixels of one scanline
// The largest scanned-out frame, per side, that a board takes (spec §5: its input limit can
// be raised to 4096 x 4096 at most); a larger file is no frame of this system.
inline constexpr int kMaxFrameSide = 4096;

struct StripHeader {
  StripOp op = StripOp::End;
  bool frame = false;  // frame parity
  std::uint8_t display = 0;
  std::uint16_t x = 0;
  std::uint16_t y = 0;
  std::uint16_t width = 0;

  friend bool operator==(const StripHeader&, const StripHeader&) = default;

  static StripHeader end() { return {}; }
  static StripHeader copy(bool frame, int display, int x, int y, int width);
  static StripHeader skip(bool frame, int width);
};

namespace header_bits {
inline constexpr int kOpShift = 46;
inline constexpr int kFrameShift = 45;
inline constexpr int kDisplayShift = 39;
inline constexpr int kXShift = 27;
inline constexpr int kYShift = 15;
inline constexpr int kWidthShift = 3;
inline constexpr std::uint64_t k12Bits = 0xFFF;
inline constexpr std::uint64_t kMask48 = (std::uint64_t{1} << 48) - 1;

// The CRC remainder is linear in the message, so it is the XOR of the remainders of each byte
// of M(x)·x^3 in its place: six 256-entry tables built at compile time. Decoding a header is
// then a handful of loads, inline in the router's per-strip loop.
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
inline constexpr Crc3Tables kCrc3;
}  // namespace header_bits

// CRC-3 (generator x^3 + x + 1) of header bits 47..3, given the 45 message bits right-aligned.
inline std::uint8_t crc3(std::uint64_t message45) {
  using header_bits::kCrc3;
  const std::uint64_t v = (message45 << 3) & header_bits::kMask48;
  return kCrc3.byte[0][v & 0xFF] ^ kCrc3.byte[1][v >> 8 & 0xFF] ^ kCrc3.byte[2][v >> 16 & 0xFF] ^
         kCrc3.byte[3][v >> 24 & 0xFF] ^ kCrc3.byte[4][v >> 32 & 0xFF] ^
         kCrc3.byte[5][v >> 40 & 0xFF];
}

// The 48-bit value H, check bits included. Throws std::out_of_range when a field does not fit
// its width (display > 63, x/y/width > 4095), because a silently masked field routes a strip to
// the wrong place.
std::uint64_t encode(const StripHeader& header);

// Decodes H; nullopt when the check bits do not match. Bits above 47 are ignored.
inline std::optional<StripHeader> decode(std::uint64_t value) {
  using namespace header_bits;
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

// H from two pixels whose first three bytes are R, G, B (RGB or RGBA layout alike).
inline std::uint64_t header_value(const std::uint8_t* p0, const std::uint8_t* p1) {
  return std::uint64_t{p0[0]} << 40 | std::uint64_t{p0[1]} << 32 | std::uint64_t{p0[2]} << 24 |
         std::uint64_t{p1[0]} << 16 | std::uint64_t{p1[1]} << 8 | std::uint64_t{p1[2]};
}

// Writes H into two pixels of `bytes_per_pixel` bytes each (3 = RGB, 4 = RGBA: A set to 255).
void write_header_pixels(std::uint64_t value, std::uint8_t* first_pixel, int bytes_per_pixel);

// "COPY f=1 d=5 x=640 y=480 w=320" — for reports and error messages.
std::string to_string(const StripHeader& header);
const char* to_string(StripOp op);

}  // namespace l2
