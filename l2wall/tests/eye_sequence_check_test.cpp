// The active stereo check, fed records directly: displays stepping through eye frames 0, 1, 2, 3
// (left and right of frames 0 and 1) pass and count two pairs, a held eye frame is counted, and
// a display that skips an eye or steps back is named with refresh, display, rank and both eyes.
#include "l2wall/eye_sequence_check.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

// Displays 0 (rank 1) and 1 (rank 2) showing eye frame `a` and `b`.
std::vector<DisplayShown> two(int a, int b) {
  return {{0, a, 1}, {1, b, 2}};
}

TEST(EyeSequenceCheck, LeftThenRightOfEachFrameCountsPairs) {
  EyeSequenceCheck check;
  std::uint64_t refresh = 0;
  for (const int f : {-1, 0, 1, 1, 2, 3}) EXPECT_TRUE(check.check(refresh++, two(f, f)).ok()) << f;
  EXPECT_EQ(check.pairs(), 2);
  EXPECT_EQ(check.displays(), 2);
  EXPECT_EQ(check.held(), 2u);  // eye frame 1 kept for a second refresh on both displays
}

TEST(EyeSequenceCheck, PairsAreTheFewestAnyDisplayCompleted) {
  EyeSequenceCheck check;
  EXPECT_TRUE(check.check(0, two(0, 0)).ok());
  EXPECT_TRUE(check.check(1, two(1, 0)).ok());
  EXPECT_EQ(check.pairs(), 0);
  EXPECT_TRUE(check.check(2, two(1, 1)).ok());
  EXPECT_EQ(check.pairs(), 1);
}

TEST(EyeSequenceCheck, AFirstFrameOtherThanFrameZerosLeftEyeIsNamed) {
  EyeSequenceCheck check;
  EXPECT_EQ(check.check(4, two(2, 2)).reason(),
            "active stereo pair broken in refresh 4: display 0 (rank 1) shows eye frame 2 "
            "(frame 1's left eye) after no frame");
}

TEST(EyeSequenceCheck, SkippingAnEyeIsNamed) {
  EyeSequenceCheck check;
  EXPECT_TRUE(check.check(0, two(0, 0)).ok());
  EXPECT_EQ(check.check(1, two(1, 2)).reason(),
            "active stereo pair broken in refresh 1: display 1 (rank 2) shows eye frame 2 "
            "(frame 1's left eye) after eye frame 0 (frame 0's left eye)");
}

TEST(EyeSequenceCheck, AFirstFrameThatIsARightEyeIsNamed) {
  EyeSequenceCheck check;
  EXPECT_EQ(check.check(0, two(-1, 1)).reason(),
            "active stereo pair broken in refresh 0: display 1 (rank 2) shows eye frame 1 "
            "(frame 0's right eye) after no frame");
}

TEST(EyeSequenceCheck, SteppingBackIsNamed) {
  EyeSequenceCheck check;
  for (const int f : {0, 1, 2})
    EXPECT_TRUE(check.check(static_cast<std::uint64_t>(f), two(f, f)).ok());
  EXPECT_EQ(check.check(3, two(1, 2)).reason(),
            "active stereo pair broken in refresh 3: display 0 (rank 1) shows eye frame 1 "
            "(frame 0's right eye) after eye frame 2 (frame 1's left eye)");
}

}  // namespace
}  // namespace l2
