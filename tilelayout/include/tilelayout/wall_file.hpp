// Reading a wall file (TOML, format in docs/wall-file.md) into a Wall, with every check that
// can be made without planning: one-line errors naming file, line and field.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "tilelayout/wall.hpp"

namespace l2 {

// Parses wall-file text; `path_for_messages` prefixes every error and becomes Wall::source.
// Throws LayoutError ("walls/x.toml:12: tiling.tile_width: must be 1..4095, got 0").
Wall parse_wall(std::string_view toml_text, const std::filesystem::path& path_for_messages);

// Reads and parses a wall file. Throws LayoutError, also when the file cannot be read.
Wall load_wall(const std::filesystem::path& path);

// The built-in default wall: the text of walls/kd-2x2.toml, embedded at build time.
std::string_view default_wall_toml();
Wall default_wall();

}  // namespace l2
