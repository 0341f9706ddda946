// A grey map (one byte a pixel, row by row) brought to another size: an MPCDI calibration's
// alpha or beta map, which may be coarser than its projector's raster, resampled to the
// display's size that the wall's maps must have. Pure; no files.
//
// Example: resample_grey({0, 255}, 2, 1, 4, 1) is {0, 64, 191, 255}.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace l2 {

// Bilinear, pixel areas aligned: output pixel x samples the input at (x + 0.5) * in_width /
// out_width - 0.5 (likewise y), clamped to the edge pixels' centres, the mix rounded, halves up.
// Throws std::invalid_argument when `in` is not in_width x in_height bytes or a side is below 1.
std::vector<std::uint8_t> resample_grey(std::span<const std::uint8_t> in, int in_width,
                                        int in_height, int out_width, int out_height);

}  // namespace l2
