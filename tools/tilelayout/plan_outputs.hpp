// The files `tilelayout --png` and `--scanout` write for one plan (of a wall, or of one mesh of
// a wall of several).
#pragma once

#include <filesystem>

#include "tilelayout/test_frame.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// DIR/pipeserver-N.png, DIR/wall.png and a depth wall's DIR/wall-layer-N.png, each line said.
// Throws std::runtime_error when a file cannot be written.
void write_pictures(const TileLayout& layout, const std::filesystem::path& dir);

// DIR/scanout-N.png: the frame each pipeserver scans out, every header drawn, every tile
// filled with the routing test pattern.
void write_scanout(const TileLayout& layout, const std::filesystem::path& dir, bool parity,
                   PatternPlace place);

}  // namespace l2
