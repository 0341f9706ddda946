// The rows a pipeserver's tiles take packed at a framebuffer width with rows unbounded: what
// the framebuffer height must be for them (suggest_fit, survival).
#pragma once

#include <optional>
#include <vector>

#include "tilelayout/tile_layout.hpp"

namespace l2 {

// None when a tile is wider than the framebuffer or cannot be encoded.
std::optional<int> needed_height(const std::vector<DisplayTile>& tiles, int width);

// The rows the fullest of `lists` needs at `width`; none as for needed_height.
std::optional<int> tallest(const std::vector<std::vector<DisplayTile>>& lists, int width);

}  // namespace l2
