// The frame number each live pipeserver writes into the first pixel of its first tile (see
// pipeserver/src/live_mode.hpp). Reading it back from an input or a display tells which
// application frame is there: the run measures latency from pixels, not from its own counters.
#pragma once

#include <cstdint>

namespace l2 {

// Where a frame's stamp is: its pipeserver's first tile's framebuffer pixel and the display pixel
// it lands on (they move with the layout).
struct StampSpot {
  int fb_x = 0, fb_y = 0, display = 0, dx = 0, dy = 0;
  bool operator==(const StampSpot&) const = default;
};

inline int decode_stamp(const std::uint8_t* rgb) {
  return rgb[0] | (rgb[1] << 8) | (rgb[2] << 16);
}

}  // namespace l2
