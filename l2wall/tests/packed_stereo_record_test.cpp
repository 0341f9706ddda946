// The packed stereo record, fed records directly: each display's frames are counted when its
// stamp changes (a held frame and "no frame yet" are not frames), the summary names the halves
// of the wall's mode and the fewest frames any display showed.
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

// Displays 0 (rank 1) and 1 (rank 2) showing frame `a` and `b`.
std::vector<DisplayShown> two(int a, int b) {
  return {{0, a, 1}, {1, b, 2}};
}

TEST(PackedStereoRecord, CountsEachDisplaysFramesAndSaysTheFewest) {
  PackedStereoRecord record(packed_wall(StereoMode::SideBySide));
  for (const auto& [a, b] : {std::pair{-1, -1}, {0, -1}, {0, 0}, {1, 0}, {1, 1}, {2, 1}})
    record.take(two(a, b));
  EXPECT_EQ(record.fewest_frames(), 2);  // display 1 showed frames 0 and 1, display 0 three
  EXPECT_EQ(record.summary_line(6),
            "packed stereo (side-by-side): each of 2 display(s) showed both eyes of each of its "
            "frames in its two halves in the same refresh (left half: left eye, right half: "
            "right eye), at least 2 frame(s) each by their stamps, in all 6 refreshes\n");
}

TEST(PackedStereoRecord, TopBottomNamesItsHalvesAndIgnoresUnknownDisplays) {
  PackedStereoRecord record(packed_wall(StereoMode::TopBottom));
  record.take(std::vector<DisplayShown>{{0, 0, 0}, {1, 0, 0}, {7, 3, 0}, {-1, 3, 0}});
  EXPECT_EQ(record.summary_line(1),
            "packed stereo (top-bottom): each of 2 display(s) showed both eyes of each of its "
            "frames in its two halves in the same refresh (top half: left eye, bottom half: "
            "right eye), at least 1 frame(s) each by their stamps, in all 1 refreshes\n");
}

}  // namespace
}  // namespace l2::packed_record_test
