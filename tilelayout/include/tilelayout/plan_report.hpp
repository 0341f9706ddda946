// The plan as text for people: per pipeserver its tiles, where they are packed and how much of
// the framebuffer they use; per display its coverage. What `tilelayout WALL.toml` prints.
#pragma once

#include <string>

#include "tilelayout/tile_layout.hpp"

namespace l2 {

std::string format_plan(const TileLayout& layout);

}  // namespace l2
