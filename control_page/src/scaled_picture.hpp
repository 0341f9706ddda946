// A display's picture made small for the page: every Nth pixel of every Nth row. Nearest, not
// filtered: each pixel shown is one the display has.
#pragma once

#include "image/rgb_image.hpp"

namespace l2 {

// A picture of ceil(width / n) x ceil(height / n); n >= 1.
RgbImage every_nth_pixel(const RgbImage& picture, int n);

}  // namespace l2
