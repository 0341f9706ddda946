// The frame number each live host writes into the first pixel of its first tile (see
// pipeserver/src/live_host.hpp). Reading it back from an input or a display tells which
// application frame is there: the run measures latency from pixels, not from its own counters.
#pragma once

#include <cstdint>

namespace l2 {

inline int decode_stamp(const std::uint8_t* rgb) {
  return rgb[0] | (rgb[1] << 8) | (rgb[2] << 16);
}

}  // namespace l2
