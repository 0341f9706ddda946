// What a wall asks of a network when it runs across machines (l2wall run --mpi): per board
// column, the frames of the inputs that feed it as scanned out, and of them the pixels of the
// strips that land on its own displays — the most that can change in a frame, since only
// changed rows travel and other columns' strips travel black (dvi_link/frame_delta.hpp).
#pragma once

#include <string>

#include "tilelayout/tile_layout.hpp"

namespace l2 {

std::string format_network_needs(const TileLayout& layout);

}  // namespace l2
