// Swap-lock groups on screen (spec §6): the windows of one group must present the same frame, so
// they are swapped back to back from one thread after all of them are drawn.
#pragma once

#include <vector>

#include "tilelayout/wall.hpp"

namespace l2 {

// Display indices grouped by swap_group, groups in ascending group number, displays in wall
// order within a group.
std::vector<std::vector<int>> swap_groups(const Wall& wall);

}  // namespace l2
