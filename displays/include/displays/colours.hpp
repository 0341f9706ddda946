// The colours the wall window adds around the displays' own pixels.
#pragma once

#include "image/rgb_image.hpp"

namespace l2 {

inline constexpr Rgb kMullionColour{24, 24, 28};  // the dark bars between displays
inline constexpr Rgb kOverlayTextColour{210, 210, 210};

}  // namespace l2
