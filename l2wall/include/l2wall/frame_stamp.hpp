// The frame number each live pipeserver writes into its framebuffer's stamp strip, a pixel the
// mesh reads and routes to no display (tilelayout/tile_layout.hpp; without room for one, its
// first tile's first pixel). Read back from each input it tells which application frame the
// input carries; the board columns follow those frames into the displays they route them to
// (board_column.hpp): the run measures latency from pixels, not from its own counters, and the
// displays show the picture unmarked.
#pragma once

#include <cstdint>

namespace l2 {

// Where a frame's stamp is: its framebuffer pixel, and the display its pipeserver's first tile
// goes to, whose frame the run asks for (they move with the layout).
struct StampSpot {
  int fb_x = 0, fb_y = 0, display = 0, dx = 0, dy = 0;
  bool operator==(const StampSpot&) const = default;
};

inline int decode_stamp(const std::uint8_t* rgb) {
  return rgb[0] | (rgb[1] << 8) | (rgb[2] << 16);
}

}  // namespace l2
