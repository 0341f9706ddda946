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

// CRC-3 (generator x^3 + x + 1) of header bits 47..3, given the 45 message bits right-aligned.
std::uint8_t crc3(std::uint64_t message45);

// The 48-bit value H, check bits included. Throws std::out_of_range when a field does not fit
// its width (display > 63, x/y/width > 4095), because a silently masked field routes a strip to
// the wrong place.
std::uint64_t encode(const StripHeader& header);

// Decodes H; nullopt when the check bits do not match. Bits above 47 are ignored.
std::optional<StripHeader> decode(std::uint64_t value);

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
