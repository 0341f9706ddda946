#include "displays/swap_groups.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(SwapGroups, GroupsDisplaysByGroupNumberInWallOrder) {
  Wall wall;
  for (int g : {2, 0, 2, 1, 0}) {
    Display d;
    d.id = static_cast<int>(wall.displays.size());
    d.swap_group = g;
    wall.displays.push_back(d);
  }
  EXPECT_EQ(swap_groups(wall), (std::vector<std::vector<int>>{{1, 4}, {3}, {0, 2}}));
  EXPECT_TRUE(swap_groups(Wall{}).empty());
}

}  // namespace
}  // namespace l2
