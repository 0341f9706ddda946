// PNG files at the edge of the system, through OpenImageIO (PNG reading: libpng). Errors name
// the file.
#pragma once

#include <filesystem>

#include "image/rgb_image.hpp"

namespace l2 {

// Writes 8-bit RGB PNG; creates parent folders. Throws std::runtime_error naming the file (and
// why, where the system says: "out/display-2.png: cannot write: a folder, not a file").
void write_png(const std::filesystem::path& path, const RgbImage& image);

// The largest side read_png() accepts: every picture the project reads is an input frame
// (8192 at most, the DVI link's limit) or one display (16384 at most, the vizserver's).
inline constexpr int kMaxPictureSide = 16384;

// Reads a PNG (with libpng) or any other 2-D picture OpenImageIO reads. An alpha channel is
// dropped, as a DVI link drops it (spec §1); grey is expanded to RGB; 16 bits become 8. Throws
// std::runtime_error naming the file and why, in one line ("the PNG file ends early
// (truncated)", "a damaged PNG (IHDR: CRC error)"; nothing is printed), also for a picture with
// a side over kMaxPictureSide (before allocating anything) and for a volume or deep image.
RgbImage read_png(const std::filesystem::path& path);

}  // namespace l2
