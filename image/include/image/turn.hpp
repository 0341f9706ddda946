// Pictures turned between a panel's raster and its canvas rectangle (orientation.hpp): what a
// turned panel must show, made from the canvas rendered upright, and a panel's frame turned
// back so a window or a page can draw it as it hangs.
#pragma once

#include "image/orientation.hpp"
#include "image/rgb_image.hpp"

namespace l2 {

// The panel's frame (its native width x height) from `canvas`, its canvas rectangle upright.
RgbImage to_panel(const RgbImage& canvas, Orientation o);
// The inverse: the canvas rectangle a panel's `frame` covers, upright, as the wall shows it.
RgbImage to_canvas(const RgbImage& frame, Orientation o);

}  // namespace l2
