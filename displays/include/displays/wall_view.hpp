// Where a wall's displays land in one window: the whole wall as the wall file places it, scaled
// down only when it does not fit, mullions (the gaps between displays) left as dark bars, and a
// text bar below for the overlay line. Pure geometry; the window code only draws what it says.
#pragma once

#include <vector>

#include "tilelayout/geometry.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

struct WallView {
  int width = 0, height = 0;        // the whole window, overlay bar included
  double scale = 1.0;               // window pixels per canvas pixel, never above 1
  std::vector<Rect> display_rects;  // displays[i] in window pixels (integer, top-left origin)
  Rect overlay;                     // the text bar below the wall (empty when overlay_height 0)
};

// The bounding box of all displays on the canvas: what the wall looks like physically.
Rect wall_extent(const Wall& wall);

// Fits the wall into max_width x (max_height - overlay_height). At scale 1 every display rect
// has exactly the display's size, so a native-size image is shown pixel for pixel.
// Throws std::invalid_argument for a wall without displays or a space too small to show it.
WallView fit_wall(const Wall& wall, int max_width, int max_height, int overlay_height);

// One display alone, centred in a width x height screen (the fullscreen case): native size when
// it fits, scaled down keeping its aspect otherwise.
Rect fit_display(int display_width, int display_height, int width, int height);

}  // namespace l2
