#include "balance/assign_heaviest.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace l2 {

std::vector<int> assign_heaviest_first(const std::vector<double>& cost, int pipeservers) {
  std::vector<int> order(cost.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost[a] > cost[b]; });
  std::vector<double> load(static_cast<std::size_t>(pipeservers), 0.0);
  std::vector<int> count(static_cast<std::size_t>(pipeservers), 0);
  std::vector<int> out(cost.size(), 0);
  for (int t : order) {
    int best = 0;
    for (int s = 1; s < pipeservers; ++s) {
      if (std::tie(load[s], count[s]) < std::tie(load[best], count[best])) best = s;
    }
    out[t] = best;
    load[best] += cost[t];
    ++count[best];
  }
  return out;
}

}  // namespace l2
