// A picture of one display's check for the person debugging a routing, after the golden diff
// pictures: what the display shows, dimmed to a quarter, every wrong pixel in the colour of its
// kind, every misplaced run framed in white, a margin right and below standing for the canvas
// past the display's edges (strip pixels that fell there drawn in it), and a legend with the
// counts underneath.
#pragma once

#include <span>

#include "image/rgb_image.hpp"
#include "verify/routing_check.hpp"

namespace l2 {

inline constexpr Rgb kMissingColour{255, 0, 255}, kMisplacedColour{255, 0, 0},
    kTwiceColour{255, 255, 0}, kMullionColour{0, 255, 255}, kMarginColour{40, 40, 40},
    kRunMarker{255, 255, 255};
// Misplaced runs framed per display, at most (more frames would hide the display).
inline constexpr int kMarkedRuns = 1000;

// Margin width in pixels: a hundredth of the display's larger side, at least 8.
int check_margin(const DisplayCheck& display);

// The picture of check.displays[index]; `shown` is what that display shows (display size).
RgbImage check_picture(const RoutingCheck& check, std::size_t index, const RgbImage& shown);

}  // namespace l2
