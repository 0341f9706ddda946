#include "frame_ranges.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(FrameRanges, RunsOfFramesAreRanges) {
  EXPECT_EQ(frame_ranges({}), "");
  EXPECT_EQ(frame_ranges({5}), "5");
  EXPECT_EQ(frame_ranges({0, 1}), "0-1");
  EXPECT_EQ(frame_ranges({0, 1, 2, 3, 7, 9, 10, 11, 12}), "0-3, 7, 9-12");
  std::vector<int> all;
  for (int f = 0; f < 399; ++f) all.push_back(f);
  EXPECT_EQ(frame_ranges(all), "0-398");
}

}  // namespace
}  // namespace l2
