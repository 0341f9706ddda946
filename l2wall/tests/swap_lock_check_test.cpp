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

// A passive stereo wall: displays 0 and 1 the left eye's, 2 and 3 their right-eye twins, all of
// one swap group.
SwapLockCheck stereo_check() {
  return SwapLockCheck({SwapGroup{0, {0, 1, 2, 3}, 0}}, {{0, 2}, {1, 3}});
}

TEST(SwapLockCheck, BothEyesOfOneFramePass) {
  const std::vector<DisplayShown> shown{{0, 6, 0}, {1, 6, 0}, {2, 6, 0}, {3, 6, 0}};
  EXPECT_TRUE(stereo_check().check(4, shown).ok());
}

TEST(SwapLockCheck, AnEyeOfAnotherFrameIsNamed) {
  // Out of swap lock within the group too; the pair's own line names both eyes once the group's
  // check is left out (a check of pairs alone, as when twins are in groups of their own).
  const SwapLockCheck pairs_only({}, {{0, 2}, {1, 3}});
  const std::vector<DisplayShown> shown{{0, 6, 0}, {1, 6, 0}, {2, 6, 0}, {3, 5, 1}};
  EXPECT_EQ(pairs_only.check(4, shown).reason(),
            "stereo pair broken in refresh 4: left eye display 1 (rank 0) shows frame 6, right "
            "eye display 3 (rank 1) frame 5");
  EXPECT_EQ(stereo_check().check(4, shown).reason(),
            "swap lock broken in refresh 4: group 0: display 3 (rank 1) shows frame 5, display 0 "
            "(rank 0) frame 6");
}

TEST(SwapLockCheck, AnEyeWithoutAFrameBesideOneWithIsNamed) {
  const SwapLockCheck pairs_only({}, {{0, 2}});
  const std::vector<DisplayShown> shown{{0, 0, 0}, {2, -1, 0}};
  EXPECT_EQ(pairs_only.check(0, shown).reason(),
            "stereo pair broken in refresh 0: left eye display 0 (rank 0) shows frame 0, right "
            "eye display 2 (rank 0) frame -1");
  EXPECT_TRUE(pairs_only.check(0, std::vector<DisplayShown>{{0, -1, 0}, {2, -1, 0}}).ok());
}

}  // namespace
}  // namespace l2
