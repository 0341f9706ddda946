// A geometry warp of a display's picture (docs/wall-file.md, "Warping projected pictures"): for
// each output pixel, the position in the display's own reassembled frame it shows, held in fixed
// point so that every run turns the same picture into the same bytes.
//
// Owns the per-pixel source positions and the sampling rule; no files (the PFM a wall names is
// read by tilelayout/warp_file.hpp) and no knowledge of the display stage that applies it.
//
// Example, a 2x1 display whose pixels swap places (a mirror):
//   const WarpMap m = warp_map_from_positions(2, 1, 2, 1, {0.75f, 0.5f, 0.25f, 0.5f});
//   apply_warp(m, raw, shown);   // shown(0, 0) = raw(1, 0), shown(1, 0) = raw(0, 0)
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "image/rgb_image.hpp"

namespace l2 {

// Source positions are in 1/kWarpOne of a pixel.
inline constexpr int kWarpOne = 256;
// A source x of an output pixel that shows black (its position was NaN or off the frame).
inline constexpr std::int32_t kWarpBlack = -1;

struct WarpMap {
  int width = 0, height = 0;  // of the output, and of the frame it samples
  // Per output pixel, row by row: x then y of the source position in 1/kWarpOne pixel, pixel
  // centres at multiples of kWarpOne, clamped to the centres of the edge pixels; x is kWarpBlack
  // for a pixel that shows black.
  std::vector<std::int32_t> source;
};

// The map of a width x height display from normalised positions (x, y) on a grid of
// grid_width x grid_height points, row by row from the top: (0, 0) is the top-left corner of the
// frame, (1, 1) its bottom-right corner. A grid the display's size gives each output pixel its
// own position; a coarser one (at least 2 points each way) spreads its points evenly over the
// output pixels' centres, the first and last on the edge pixels, and each output pixel's
// position is the bilinear mix of the four points around it, worked in double. A position with
// a NaN or a coordinate outside 0..1 shows black; the others become x * width - 1/2 and
// y * height - 1/2 pixels, rounded to 1/kWarpOne (halves up), then clamped to the edge pixels'
// centres. Throws std::invalid_argument when the grid is larger than the display, a side of it
// is 1 on a display wider than 1, or `positions` is not 2 numbers per point.
WarpMap warp_map_from_positions(int width, int height, int grid_width, int grid_height,
                                std::span<const float> positions);

// Whether every output pixel shows its own source pixel: a map that changes nothing.
bool is_identity(const WarpMap& map);

// `out` becomes `in` as the map shows it (resized to `in`'s size when it differs): each output
// pixel the bilinear mix of the four source pixels around its position, with weights in
// 1/kWarpOne, (top row mixed across x) * (1 - fy) + (bottom row mixed across x) * fy, taken to a
// byte by adding 1/2 and dropping the fraction. `in` must be the map's size
// (std::invalid_argument otherwise) and must not be `out`.
void apply_warp(const WarpMap& map, const RgbImage& in, RgbImage& out);

}  // namespace l2
