// A colour for every display pixel from which the pixel's destination can be read back, so a
// scanned-out frame (or a display buffer after routing) can be checked pixel by pixel without
// any rendering: each tile pixel carries where it must end up.
//
// Formula (24 bits, R the most significant byte):
//
//     v        = (x & 0xFFF) << 12 | (y & 0xFFF)
//     mask(d)  = ((d + 1) * 0x5BD1E9) & 0xFFFFFF      -- odd multiplier: distinct and non-zero
//                                                       for every display 0..63
//     colour   = v ^ mask(d)         R = colour >> 16, G = colour >> 8 & 0xFF, B = colour & 0xFF
//
// Inverse: v = colour ^ mask(d), x = v >> 12, y = v & 0xFFF. Because the mask differs per
// display, a strip delivered to the wrong display decodes to a different position, as does a
// strip delivered to the wrong row or column; comparing the decoded position with the pixel's
// real position catches both.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>

#include "image/rgb_image.hpp"

namespace l2 {

// The per-display XOR mask of the formula above (24 bits).
unsigned test_pattern_mask(int display);

// The colour display `display` should show at its pixel (x, y); x and y are taken modulo 4096.
Rgb test_pattern(int display, int x, int y);

// The (x, y) that test_pattern(display, x, y) encodes into `colour`; nullopt when `display` is
// not 0..63. Every colour decodes to some position: compare it with the expected one.
std::optional<std::pair<int, int>> test_pattern_position(int display, Rgb colour);

// Compositing tiles (spec §7) carry the pattern so that their composite is known too.
//
// DEPTH: every display pixel of a depth wall gets one winning layer, w = h mod layers (h a hash
// of display, x and y), which sends the pattern colour at a depth b (1..FFEFFF, from h). Every
// other layer sends a wrong colour (the pattern with its top bit flipped, so it decodes 2048
// columns away) and loses: a layer before w on the bus at a greater depth or the far plane,
// one after w at the same depth b (a tie, which the earlier strip keeps) or a greater one. So
// the composite shows the plain pattern exactly when every rule of §7 was applied.
struct LayerPixel {
  Rgb colour;
  std::uint32_t depth = 0;  // 0 nearest .. FFFFFF the far plane
};
LayerPixel depth_test_pixel(int display, int x, int y, int layer, int layers);

// KEY: the overlay's pattern is the plain pattern with 4x4 blocks in a checkerboard left
// transparent (sent as the key colour), through which what the other pipeservers route shows.
bool key_test_transparent(int x, int y);

}  // namespace l2
