// The depth half of a DEPTH tile (spec §7): the 24-bit depth buffer read back under each DEPTH
// tile and written, as pixels D = R<<16 | G<<8 | B, into the w columns after the tile's colour
// pixels of the scanned-out frame.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tilelayout/tile_layout.hpp"

namespace l2 {

// Depth of a cleared pixel: the far plane, which never wins a composite.
inline constexpr std::uint32_t kFarDepth = 0xFFFFFF;

// Reads the depth under every DEPTH tile of `plan` from the current GL context (its
// framebuffer fb_width x fb_height, rendered and finished) into `frame`, the scanned-out RGB
// frame (rows top to bottom). A depth `far_as` replaces the far plane: layer 0 of a depth wall
// sends its cleared pixels one step nearer, so the scene's clear colour shows where no layer
// draws, as in a whole-frame render, yet behind every fragment one would keep (the camera keeps
// the scene well inside the far plane). Throws std::invalid_argument when `frame` is smaller
// than the framebuffer.
void scan_out_depth(const ServerPlan& plan, std::uint32_t far_as, std::span<std::uint8_t> frame);

}  // namespace l2
