// A picture whose pixels are each looked up in one of a few colour tables, chosen per pixel:
// what a display whose correction differs across it (an edge-blended projector,
// tilelayout/blend_map.hpp) applies to every frame.
//
// Owns the per-pixel choice and the tables; no geometry (what the indexes mean is its maker's).
//
// Example:
//   TableMap m{.width = 2, .height = 1, .index = {0, 1}, .tables = {ColourTable::identity(),
//   half}}; apply_table_map(m, raw, shown);   // shown(0, 0) = raw(0, 0); shown(1, 0) through
//   `half`
#pragma once

#include <cstdint>
#include <vector>

#include "image/colour_table.hpp"
#include "image/rgb_image.hpp"

namespace l2 {

struct TableMap {
  int width = 0, height = 0;
  std::vector<std::uint16_t> index;  // per pixel, row by row: which of `tables`
  std::vector<ColourTable> tables;
};

// `out` becomes `in` with every byte looked up in its channel of its pixel's table (resized to
// `in`'s size when it differs). `in` must be the map's size (std::invalid_argument otherwise).
// `in` and `out` may be the same picture.
void apply_table_map(const TableMap& map, const RgbImage& in, RgbImage& out);

}  // namespace l2
