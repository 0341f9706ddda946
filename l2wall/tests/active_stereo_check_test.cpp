// The active stereo check, fed the eye frames two displays show (after the quad buffer) directly:
// a strictly alternating sequence passes and counts its pairs, new and repeated; an eye shown in
// a refresh of the other parity (a lone eye kept), a pair changed at a right-eye refresh, two
// displays of the group on different frames, a frame stepping back and nothing after a pair are
// each named in one line with refresh, display and rank. Its per-refresh record is bounded.
#include "l2wall/active_stereo_check.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace l2 {
namespace {

// Displays 0 (rank 1) and 1 (rank 2) showing eye frame `a` and `b` (2k + eye, -1 nothing).
std::vector<DisplayShown> two(int a, int b) {
  return {{0, a, 1}, {1, b, 2}};
}

// Feeds `frames` (both displays alike) from refresh 0; all must pass.
void feed(ActiveStereoCheck& check, std::initializer_list<int> frames) {
  std::uint64_t refresh = 0;
  for (const int f : frames) ASSERT_TRUE(check.check(refresh++, two(f, f)).ok()) << f;
}

TEST(ActiveStereoCheck, AlternatingPairsPassAndAreCounted) {
  ActiveStereoCheck check;
  feed(check, {-1, -1, 0, 1, 0, 1, 2, 3});
  EXPECT_EQ(check.refreshes(), 8u);
  EXPECT_EQ(check.first_pair(), 2);
  EXPECT_EQ(check.pairs_shown(), 3u);     // frame 0, frame 0 again, frame 1
  EXPECT_EQ(check.pairs_repeated(), 1u);  // frame 0's second showing
}

TEST(ActiveStereoCheck, ItsRecordSaysEachRefreshsEyeAndFrameUpToItsRows) {
  ActiveStereoCheck check(4);
  feed(check, {-1, -1, 0, 1});
  EXPECT_EQ(check.csv(), "refresh,eye,frame\n0,none,\n1,none,\n2,left,0\n3,right,0\n");
  EXPECT_FALSE(check.csv_cut());
  ASSERT_TRUE(check.check(4, two(2, 2)).ok());
  EXPECT_EQ(check.csv(), "refresh,eye,frame\n0,none,\n1,none,\n2,left,0\n3,right,0\n");
  EXPECT_TRUE(check.csv_cut());
}

TEST(ActiveStereoCheck, ALoneEyeKeptIntoTheNextRefreshIsNamed) {
  ActiveStereoCheck check;
  feed(check, {0, 1});
  EXPECT_EQ(check.check(2, two(1, 1)).reason(),
            "active stereo broken in refresh 2 (left eye): display 0 (rank 1) shows frame 0's "
            "right eye");
}

TEST(ActiveStereoCheck, APairChangedAtARightEyeRefreshIsNamed) {
  ActiveStereoCheck check;
  feed(check, {0});
  EXPECT_EQ(check.check(1, two(3, 3)).reason(),
            "active stereo broken in refresh 1 (right eye): display 0 (rank 1) shows frame 1's "
            "right eye after frame 0's left eye");
}

TEST(ActiveStereoCheck, AFirstPairStartingWithItsRightEyeIsNamed) {
  ActiveStereoCheck check;
  feed(check, {-1});
  EXPECT_EQ(check.check(1, two(1, 1)).reason(),
            "active stereo broken in refresh 1 (right eye): display 0 (rank 1) shows frame 0's "
            "right eye after nothing");
}

TEST(ActiveStereoCheck, DisplaysOfTheGroupOnDifferentFramesAreNamed) {
  ActiveStereoCheck check;
  EXPECT_EQ(check.check(0, two(0, 2)).reason(),
            "active stereo broken in refresh 0 (left eye): display 1 (rank 2) shows frame 1's "
            "left eye, another display of its swap group frame 0");
}

TEST(ActiveStereoCheck, SteppingBackIsNamed) {
  ActiveStereoCheck check;
  feed(check, {2, 3});
  EXPECT_EQ(check.check(2, two(0, 0)).reason(),
            "active stereo broken in refresh 2 (left eye): display 0 (rank 1) shows frame 0's "
            "left eye after frame 1");
}

TEST(ActiveStereoCheck, NothingAfterAPairIsNamed) {
  ActiveStereoCheck check;
  feed(check, {0, 1});
  EXPECT_EQ(check.check(2, two(-1, -1)).reason(),
            "active stereo broken in refresh 2 (left eye): display 0 (rank 1) shows nothing "
            "after frame 0");
}

}  // namespace
}  // namespace l2
