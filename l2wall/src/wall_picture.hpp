// The whole wall as one picture: every display's shown image at its canvas place, mullions
// (canvas not covered by any display) dark grey.
#pragma once

#include <functional>

#include "image/rgb_image.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

RgbImage compose_wall_picture(const Wall& wall,
                              const std::function<const RgbImage&(int display)>& shown);

}  // namespace l2
