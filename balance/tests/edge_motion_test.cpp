#include "balance/edge_motion.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(EdgeMotion, HalfTheDistanceEachFrameSettlesInFiveFrames) {
  const EdgeMotion m{0.5, 2};
  double p = 0;
  const double expected[] = {50, 75, 87.5, 93.75, 96.875};
  for (double e : expected) {
    p = move_edge(p, 100, m);
    EXPECT_DOUBLE_EQ(p, e);
  }
  EXPECT_DOUBLE_EQ(move_edge(10, 0, m), 5);  // either way
}

TEST(EdgeMotion, AnEdgeWithinTheDeadBandStays) {
  EXPECT_DOUBLE_EQ(move_edge(98, 100, {0.5, 2}), 98);
  EXPECT_DOUBLE_EQ(move_edge(97.9, 100, {0.5, 2}), 98.95);
}

TEST(EdgeMotion, PixelEdgesRoundAndKeepEveryCellAPixel) {
  EXPECT_EQ(pixel_edges({0, 2.5, 7.49, 10}), (std::vector<int>{0, 3, 7, 10}));
  EXPECT_EQ(pixel_edges({0, 0.4, 0.6, 3}), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(pixel_edges({0, 9.9, 9.95, 10}), (std::vector<int>{0, 8, 9, 10}));
}

}  // namespace
}  // namespace l2
