// Edge blending of overlapping projectors (docs/wall-file.md, "Blending overlapping
// projectors"), generated from the wall: where displays' canvas rectangles overlap, each
// display's weight at each of its pixels, the weights of all displays showing a canvas pixel
// summing to exactly kBlendOne; and the per-weight tables that turn a picture's code values into
// the display's share of its light at the wall's gamma.
//
// Owns the geometry of the ramps and the weights' integer form. Pure logic on a Wall: the
// display stage (l2wall/colour_stage.hpp) applies what display_tables() returns to pictures.
//
// Example, walls/projectors-2x1-blended.toml (two 1024-wide projectors overlapping by 64):
//   blend_ramps(wall, 0)      // {.right = 64}
//   blend_weights(wall, 0)    // 1024x768 weights: 4096 left of column 960, then 4064, 4000, ...
//   display_tables(wall, 0)   // those weights as indexes of 65 tables, each blend then colour
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "image/colour_table.hpp"
#include "image/table_map.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

// A weight of 1, in the integer form the maps hold: a weight w is w * kBlendOne.
inline constexpr int kBlendOne = 4096;

// How far a display's weight ramps in from each edge, in canvas pixels: the depth of the deepest
// overlap with another display across that edge; 0 where that edge overlaps no display.
struct BlendRamps {
  int left = 0, right = 0, top = 0, bottom = 0;
  bool any() const { return left || right || top || bottom; }
};
BlendRamps blend_ramps(const Wall& wall, int display);

// The weights, in 1/kBlendOne, of every display at canvas pixel (u, v), by display id (0 for a
// display that does not show it). Every display showing it gets its share; together exactly
// kBlendOne when any display shows it.
std::vector<int> blend_weights_at(const Wall& wall, int u, int v);

// The display's weight at each of its pixels, row by row in its own raster (the panel's, as
// strip headers address it: Display::panel_map). Empty when the wall does not blend or the
// display overlaps no other.
std::vector<std::uint16_t> blend_weights(const Wall& wall, int display);

// What a weight does to a code value at `gamma`: out = round(255 * (w * (in/255)^gamma)^(1 /
// gamma)), which is in * w^(1/gamma) rounded, halves up; w^(1/gamma) is taken to 1/2^32 once and
// the table worked out in integers.
ColourTable blend_table(int weight, double gamma);

// Everything the display does to its pixels where they leave the wall, when it blends: each
// pixel's weight as the index of a table that is the weight's blend table, then the display's
// colour matching. std::nullopt when the display does not blend (its colour table alone then).
std::optional<TableMap> display_tables(const Wall& wall, int display);

}  // namespace l2
