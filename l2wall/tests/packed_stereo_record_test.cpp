// The packed stereo record, fed records directly: each display's frames are counted when its
// stamp changes (a held frame and "no frame yet" are not frames), the summary names the halves
// of the wall's mode and the fewest frames any display showed, and a display holding strips of
// an older frame than its stamp is named with refresh, display, rank and both frames.
#include "l2wall/packed_stereo_record.hpp"

#include <gtest/gtest.h>

namespace l2::packed_record_test {
namespace {

Wall packed_wall(StereoMode mode) {
  Wall w;
  w.stereo.mode = mode;
  w.displays.resize(2);
  w.displays[1].id = 1;
  return w;
}

// Displays 0 (rank 1) and 1 (rank 2) showing frame `a` and `b`, whole.
std::vector<DisplayShown> two(int a, int b) {
  return {{0, a, 1, a}, {1, b, 2, b}};
}

TEST(PackedStereoRecord, CountsEachDisplaysFramesAndSaysTheFewest) {
  PackedStereoRecord record(packed_wall(StereoMode::SideBySide));
  std::uint64_t refresh = 0;
  for (const auto& [a, b] : {std::pair{-1, -1}, {0, -1}, {0, 0}, {1, 0}, {1, 1}, {2, 1}})
    EXPECT_TRUE(record.check(refresh++, two(a, b)).ok());
  EXPECT_EQ(record.fewest_frames(), 2);  // display 1 showed frames 0 and 1, display 0 three
  EXPECT_EQ(record.summary_line(6),
            "packed stereo (side-by-side): each of 2 display(s) showed both eyes of each of its "
            "frames in its two halves in the same refresh (left half: left eye, right half: "
            "right eye; every strip of it stamped with that frame), at least 2 frame(s) each, in "
            "all 6 refreshes\n");
}

TEST(PackedStereoRecord, TopBottomNamesItsHalvesAndIgnoresUnknownDisplays) {
  PackedStereoRecord record(packed_wall(StereoMode::TopBottom));
  EXPECT_TRUE(
      record.check(0, std::vector<DisplayShown>{{0, 0, 0, 0}, {1, 0, 0, 0}, {7, 3, 0, 3}}).ok());
  EXPECT_EQ(record.summary_line(1),
            "packed stereo (top-bottom): each of 2 display(s) showed both eyes of each of its "
            "frames in its two halves in the same refresh (top half: left eye, bottom half: "
            "right eye; every strip of it stamped with that frame), at least 1 frame(s) each, in "
            "all 1 refreshes\n");
}

TEST(PackedStereoRecord, ADisplayHoldingAnOlderFramesStripsIsNamed) {
  PackedStereoRecord record(packed_wall(StereoMode::SideBySide));
  EXPECT_TRUE(record.check(0, two(4, 4)).ok());
  EXPECT_EQ(record.check(1, std::vector<DisplayShown>{{0, 5, 1, 5}, {1, 5, 2, 4}}).reason(),
            "packed stereo broken in refresh 1: display 1 (rank 2) shows frame 5, but part of it "
            "frame 4: its halves could show the eyes of two frames");
}

}  // namespace
}  // namespace l2::packed_record_test
