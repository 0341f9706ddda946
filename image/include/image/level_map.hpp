// A display's alpha and beta maps (docs/wall-file.md, "Alpha and beta maps"), as MPCDI's
// alphaMap and betaMap are: per pixel, a weight the picture is multiplied by and a black level
// it is raised to, held as one gain and one offset per pixel in fixed point, so that every run
// turns the same picture into the same bytes.
//
// Owns the per-pixel gains and offsets and the rule; no files (the PNGs a wall names are read by
// tilelayout's wall reader).
//
// Example, a 2x1 display, alpha 255 and 128, no beta:
//   const LevelMap m = level_map(2, 1, std::vector<std::uint8_t>{255, 128}, 1.0, {});
//   apply_level_map(m, raw, shown);  // shown(1, 0) = raw(1, 0) * 128/255, rounded
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "image/rgb_image.hpp"

namespace l2 {

// Gains and offsets are in 1/kLevelOne.
inline constexpr std::uint32_t kLevelOne = 1u << 16;

struct LevelMap {
  int width = 0, height = 0;
  // Per pixel, row by row: out = (in * gain + offset + kLevelOne / 2) / kLevelOne, rounded down.
  std::vector<std::uint32_t> gain, offset;
};

// The map of a width x height display from its alpha and beta maps, one byte per pixel row by
// row (either may be empty: none). With a = alpha / 255 and b = beta / 255, a pixel's code value
// `in` becomes b * 255 + in * a^(1/alpha_gamma) * (1 - b): the alpha weight taken as linear light
// at alpha_gamma (1: it multiplies code values as they are), then the black level raised to b.
// gain = round(a^(1/alpha_gamma) * (1 - b) * kLevelOne), offset = round(b * 255 * kLevelOne),
// worked in double, halves up. Throws std::invalid_argument when a non-empty map is not
// width * height bytes or alpha_gamma is not positive.
LevelMap level_map(int width, int height, std::span<const std::uint8_t> alpha, double alpha_gamma,
                   std::span<const std::uint8_t> beta);

// Whether every pixel is left as it is (gain kLevelOne, offset 0).
bool is_identity(const LevelMap& map);

// `out` becomes `in` through the map, each channel alike (resized to `in`'s size when it
// differs). `in` must be the map's size (std::invalid_argument otherwise); `in` and `out` may be
// the same picture.
void apply_level_map(const LevelMap& map, const RgbImage& in, RgbImage& out);

}  // namespace l2
