// The swap-lock check, fed records directly: one refresh in lock passes, one display a frame
// behind its group is named with refresh, group, display and rank.
#include "l2wall/swap_lock_check.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

std::vector<SwapGroup> two_groups() {
  return {SwapGroup{0, {0, 1, 8}, 0}, SwapGroup{3, {2, 9}, 0}};
}

TEST(SwapLockCheck, GroupsShowingOneFrameEachPass) {
  const SwapLockCheck check(two_groups());
  const std::vector<DisplayShown> shown{{0, 5, 9}, {1, 5, 9}, {2, 4, 9}, {8, 5, 10}, {9, 4, 10}};
  EXPECT_TRUE(check.check(17, shown).ok());
}

TEST(SwapLockCheck, DisplayBehindItsGroupOnAnotherRankIsNamed) {
  const SwapLockCheck check(two_groups());
  const std::vector<DisplayShown> shown{{0, 5, 9}, {1, 5, 9}, {2, 4, 9}, {8, 4, 10}, {9, 4, 10}};
  EXPECT_EQ(check.check(17, shown).reason(),
            "swap lock broken in refresh 17: group 0: display 8 (rank 10) shows frame 4, "
            "display 0 (rank 9) frame 5");
}

TEST(SwapLockCheck, SecondGroupIsCheckedToo) {
  const SwapLockCheck check(two_groups());
  const std::vector<DisplayShown> shown{{0, 5, 9}, {1, 5, 9}, {2, 4, 9}, {8, 5, 10}, {9, 3, 10}};
  EXPECT_EQ(check.check(2, shown).reason(),
            "swap lock broken in refresh 2: group 3: display 9 (rank 10) shows frame 3, "
            "display 2 (rank 9) frame 4");
}

TEST(SwapLockCheck, DisplaysWithoutAFrameYetAreNotCompared) {
  const SwapLockCheck check(two_groups());
  const std::vector<DisplayShown> shown{{0, -1, 9}, {1, 0, 9}, {8, 0, 10}};
  EXPECT_TRUE(check.check(0, shown).ok());
}

}  // namespace
}  // namespace l2
