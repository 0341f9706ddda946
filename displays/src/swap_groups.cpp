#include "displays/swap_groups.hpp"

#include <map>

namespace l2 {

std::vector<std::vector<int>> swap_groups(const Wall& wall) {
  std::map<int, std::vector<int>> by_group;
  for (std::size_t i = 0; i < wall.displays.size(); ++i) {
    by_group[wall.displays[i].swap_group].push_back(static_cast<int>(i));
  }
  std::vector<std::vector<int>> groups;
  for (auto& [group, members] : by_group) groups.push_back(std::move(members));
  return groups;
}

}  // namespace l2
