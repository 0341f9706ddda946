// How long a frame took and how unevenly its work was shared, from its tiles' render times.
#pragma once

#include "balance/cost_estimate.hpp"

namespace l2 {

struct FrameLoad {
  double frame_seconds = 0;  // the slowest pipeserver's render time: the frame waits for it
  double imbalance = 0;      // frame_seconds over the mean of the pipeservers (1: even)
};

FrameLoad frame_load(const TileSeconds& seconds);

}  // namespace l2
