// A 3x5 pixel digit font for labels in pictures: no font file needed. Private.
#pragma once

#include "image/rgb_image.hpp"

namespace l2 {

// Size of `value` drawn at `scale` (pixels per font pixel), one font pixel between digits.
int number_width(int value, int scale);
inline int number_height(int scale) {
  return 5 * scale;
}

// Draws `value` (>= 0) with its top-left at (x, y), clipped to the image.
void draw_number(RgbImage& image, int x, int y, int value, int scale, Rgb colour);

}  // namespace l2
