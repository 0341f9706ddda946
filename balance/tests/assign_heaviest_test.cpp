#include "balance/assign_heaviest.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(AssignHeaviestFirst, HeaviestToTheFirstToFinish) {
  // 5 -> s0 (5); 4 -> s1 (4); 3 -> s1 (7); 2 -> s0 (7); 1: both at 7 with two tiles -> s0.
  EXPECT_EQ(assign_heaviest_first({1, 5, 3, 4, 2}, 2), (std::vector<int>{0, 0, 1, 1, 0}));
}

TEST(AssignHeaviestFirst, FreeTilesStillReachEveryPipeserver) {
  EXPECT_EQ(assign_heaviest_first({0, 0, 0, 0}, 3), (std::vector<int>{0, 1, 2, 0}));
}

}  // namespace
}  // namespace l2
