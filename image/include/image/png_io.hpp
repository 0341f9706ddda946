// PNG files at the edge of the system, through OpenImageIO. Errors name the file.
#pragma once

#include <filesystem>

#include "image/rgb_image.hpp"

namespace l2 {

// Writes 8-bit RGB PNG; creates parent folders. Throws std::runtime_error naming the file.
void write_png(const std::filesystem::path& path, const RgbImage& image);

// Reads an 8-bit PNG (or any format OpenImageIO reads). An alpha channel is dropped, as a DVI
// link drops it (spec §1); grey is expanded to RGB. Throws std::runtime_error naming the file.
RgbImage read_png(const std::filesystem::path& path);

}  // namespace l2
