// The frame a pipeserver would scan out if every tile showed the routing test pattern: how a
// routing is validated without any rendering (tilelayout --scanout, routing tests).
#pragma once

#include "image/rgb_image.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// Fills every packed tile of `fb` with test_pattern(display, x, y) of its destination pixels;
// DEPTH tiles with the plan's layer of depth_test_pixel, KEY tiles with the key colour where
// key_test_transparent (test_pattern.hpp).
void fill_test_pattern(const PipeserverPlan& plan, RgbImage& fb);

// A full scanned-out frame (spec §1): black, test-pattern tiles, every header of §4 rule 3.
RgbImage test_frame(const PipeserverPlan& plan, bool frame_parity);

}  // namespace l2
