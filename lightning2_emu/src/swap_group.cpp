#include "lightning2_emu/swap_group.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "lightning2_emu/mesh.hpp"

namespace l2 {

std::vector<SwapGroup> make_swap_groups(std::span<const DisplaySpec> displays) {
  std::vector<SwapGroup> groups;
  for (const DisplaySpec& d : displays) {
    auto it = std::find_if(groups.begin(), groups.end(),
                           [&](const SwapGroup& g) { return g.id == d.swap_group; });
    if (it == groups.end()) {
      groups.push_back({d.swap_group, {}, 0});
      it = groups.end() - 1;
    }
    it->displays.push_back(d.id);
  }
  if (groups.size() > 64) {
    throw MeshError(fmt::format("{} swap-lock groups: at most 64", groups.size()));
  }
  std::sort(groups.begin(), groups.end(),
            [](const SwapGroup& a, const SwapGroup& b) { return a.id < b.id; });
  for (SwapGroup& g : groups) std::sort(g.displays.begin(), g.displays.end());
  return groups;
}

}  // namespace l2
