// The frame a pipeserver would scan out if every tile showed the routing test pattern: how a
// routing is validated without any rendering (tilelayout --scanout, routing tests).
#pragma once

#include "image/rgb_image.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// Which position of a pixel the pattern encodes. Display: its place on its display, so a frame
// checks routing alone, whatever the wall's geometry (the routing checks decode it so).
// Canvas: its place on the canvas, so the displays also show where the wall file puts each
// display (mullions, overlaps, positions): the golden images' pattern, which must see a change
// of geometry.
enum class PatternPlace { Display, Canvas };

// Fills every packed tile of `fb` with test_pattern(display, x, y) of its destination pixels
// ((x, y) as `place` says); DEPTH tiles with the plan's layer of depth_test_pixel, KEY tiles
// with the key colour where key_test_transparent (test_pattern.hpp).
void fill_test_pattern(const PipeserverPlan& plan, RgbImage& fb,
                       PatternPlace place = PatternPlace::Display);

// A full scanned-out frame (spec §1): black, test-pattern tiles, every header of §4 rule 3.
RgbImage test_frame(const PipeserverPlan& plan, bool frame_parity,
                    PatternPlace place = PatternPlace::Display);

}  // namespace l2
