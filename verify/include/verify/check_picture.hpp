// A picture of one display's check for the person debugging a routing, after the golden diff
// pictures: what the display shows, dimmed to a quarter, every wrong pixel in the colour of its
// kind, a margin right and below standing for the canvas past the display's edges (strip
// pixels that fell there drawn in it), and a legend with the counts underneath.
#pragma once

#include <span>

#include "image/rgb_image.hpp"
#include "verify/routing_check.hpp"

namespace l2 {

inline constexpr Rgb kMissingColour{255, 0, 255}, kMisplacedColour{255, 0, 0},
    kTwiceColour{255, 255, 0}, kMullionColour{0, 255, 255}, kMarginColour{40, 40, 40};

// Margin width in pixels: a hundredth of the display's larger side, at least 8.
int check_margin(const DisplayCheck& display);

// `shown` is what the display shows (display size); `mullion_runs` may hold other displays'.
RgbImage check_picture(const DisplayCheck& display, const RgbImage& shown,
                       std::span<const MullionRun> mullion_runs);

}  // namespace l2
