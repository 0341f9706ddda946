// The display images show_wall shows: DIR/display-<d>.png as the emulator writes them, and the
// stand-in wall (all displays in a row) used when no wall file is given.
#pragma once

#include <filesystem>
#include <vector>

#include "image/rgb_image.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

// display-0.png, display-1.png, ... up to the first missing number. Throws std::runtime_error
// naming the folder when there is none.
std::vector<RgbImage> read_display_files(const std::filesystem::path& dir);

// display-<d>.png for every display of `wall`, each checked against the display's size.
// Throws std::runtime_error naming the file.
std::vector<RgbImage> read_display_files(const std::filesystem::path& dir, const Wall& wall);

// A wall of the given images side by side, `gap` pixels of mullion between neighbours, tops
// aligned, one swap group.
Wall row_wall(const std::vector<RgbImage>& images, int gap);

}  // namespace l2
