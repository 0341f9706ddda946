#include "balance/frame_load.hpp"

#include <algorithm>
#include <numeric>

namespace l2 {

FrameLoad frame_load(const TileSeconds& seconds) {
  if (seconds.empty()) return {};
  double max = 0, sum = 0;
  for (const auto& pipeserver : seconds) {
    const double t = std::accumulate(pipeserver.begin(), pipeserver.end(), 0.0);
    max = std::max(max, t);
    sum += t;
  }
  const double mean = sum / double(seconds.size());
  return {max, mean > 0 ? max / mean : 1.0};
}

}  // namespace l2
