// Puts an RGB picture (rows top to bottom) into the framebuffer at a place, pixel for pixel.
#pragma once

#include "image/rgb_image.hpp"

namespace l2::detail {

// The picture's lower-left corner goes to (gl_x, gl_y) in GL window coordinates.
void draw_rgb(const RgbImage& rgb, int gl_x, int gl_y);

}  // namespace l2::detail
