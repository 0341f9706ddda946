// A picture stored as scanlines (PNG, JPEG) too large to hold decoded cannot be shown a part
// at a time: every band the image cache lets go is decoded again from the first row. Such a
// picture is copied once, before a run starts, into a tiled TIFF with MIP levels in a folder
// of copies, which later runs find and read instead.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace l2 {

// Where the copies are kept: $XDG_CACHE_HOME/lightning2/pictures, else
// $HOME/.cache/lightning2/pictures, else lightning2-pictures in the temporary folder.
std::filesystem::path tiled_copy_folder();

// The name of the copy of the picture at `absolute_path` of `size` bytes last changed at
// `mtime_ns`: a picture changed or replaced is copied anew. Pure.
std::string tiled_copy_name(const std::string& absolute_path, std::uintmax_t size,
                            std::int64_t mtime_ns);

// The environment variable that, set to a number of MiB, takes the place of the threshold
// below (lowered by the tests, to copy a small picture).
inline constexpr const char* kTiledCopyThresholdVariable = "L2_TILED_COPY_MB";

// The file to read for `picture`: itself when it is stored in tiles or takes at most
// `threshold_mb` MiB decoded as 8-bit RGB; else its tiled copy, made now (a progress line on
// stderr: "converting big.png (30000x20000) into a tiled picture with mip levels: 40%") or
// found made earlier (a line saying so). Throws std::runtime_error naming the picture, in one
// line, when it cannot be read or the copy cannot be made.
std::filesystem::path picture_to_read(const std::filesystem::path& picture, double threshold_mb);

}  // namespace l2
