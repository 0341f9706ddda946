#include "balance/edge_motion.hpp"

#include <algorithm>
#include <cmath>

namespace l2 {

double move_edge(double position, double target, const EdgeMotion& motion) {
  if (std::abs(target - position) <= motion.dead_band) return position;
  return position + motion.gain * (target - position);
}

std::vector<int> pixel_edges(const std::vector<double>& edges) {
  const int n = static_cast<int>(edges.size()) - 1;
  std::vector<int> e(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k) e[k] = static_cast<int>(std::lround(edges[k]));
  const int size = e[n];
  for (int k = 1; k < n; ++k) e[k] = std::clamp(e[k], e[k - 1] + 1, size - (n - k));
  return e;
}

}  // namespace l2
