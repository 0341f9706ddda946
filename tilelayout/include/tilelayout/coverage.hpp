// How much of each display the tiles cover: for the plan report and the uncovered-area warning.
#pragma once

#include <string>
#include <vector>

#include "tilelayout/tile_layout.hpp"

namespace l2 {

struct DisplayCoverage {
  int display = 0;
  long long pixels = 0;      // the display's pixel count
  long long covered = 0;     // pixels at least one tile covers
  long long overlapped = 0;  // pixels more than one tile covers (never, for a valid plan)
  Rect uncovered_box;        // bounding box of the uncovered pixels, display coordinates
};

std::vector<DisplayCoverage> display_coverage(const Wall& wall,
                                              const std::vector<DisplayTile>& tiles);

// One warning per display with uncovered pixels: "canvas area 600x20 at 20,460 (display 1:
// 12000 pixels) is not covered by any tile".
std::vector<std::string> coverage_warnings(const Wall& wall,
                                           const std::vector<DisplayCoverage>& coverage);

}  // namespace l2
