// Test helper: a tile of display `display` at (dx, dy), w x h, placed on the canvas where it sits
// on the display (the planner's tiles carry both rectangles; these tests need only one).
#pragma once

#include "tilelayout/tile_layout.hpp"

namespace l2 {

inline DisplayTile display_tile(int display, int dx, int dy, int w, int h) {
  DisplayTile t;
  t.display = display;
  t.on_display = {dx, dy, w, h};
  t.on_canvas = t.on_display;
  return t;
}

}  // namespace l2
