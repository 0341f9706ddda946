// Command-line values and frame files at the edge of the emulator: display lists, sizes,
// colours, folders of frames over time.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/rgb_image.hpp"
#include "lightning2_emu/display_buffers.hpp"
#include "lightning2_emu/mesh.hpp"

namespace l2 {

// "1280x1024" -> {1280, 1024}. Throws std::invalid_argument naming `what` and the text.
InputLimit parse_size(const std::string& text, const std::string& what);

// "1600x1200,1280x1024" -> displays 0, 1, ... with those sizes, all in swap group 0.
std::vector<DisplaySpec> parse_display_list(const std::string& text);

// "0,0,1,1": swap group of each display in order. Throws when the count differs.
void apply_group_list(const std::string& text, std::vector<DisplaySpec>& displays);

// "RRGGBB" (hex) -> colour.
Rgb parse_colour(const std::string& text, const std::string& what);

// The image files of a folder (png, ppm, tif, jpg...), sorted by name with numbers by value
// (frame-2 before frame-10): one input's frames over time. Throws std::runtime_error naming the
// folder when it is missing or empty. JPEG files are listed so that reading them refuses them
// by name (read_scanned_frame) rather than skipping them without a word.
std::vector<std::filesystem::path> list_frames(const std::filesystem::path& folder);

}  // namespace l2
