// resample_grey: expected bytes worked out by hand from the rule (sample at (x + 0.5) * in / out
// - 0.5, clamped to the edge centres, bilinear, halves up).
#include "image/grey_resample.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace l2 {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(GreyResample, UpscalingMixesNeighboursAndKeepsTheEdges) {
  // Samples at -0.25 (clamped to 0), 0.25, 0.75, 1.25 (clamped to 1).
  EXPECT_EQ(resample_grey(Bytes{0, 255}, 2, 1, 4, 1), (Bytes{0, 64, 191, 255}));
  // The same down a column.
  EXPECT_EQ(resample_grey(Bytes{0, 255}, 1, 2, 1, 4), (Bytes{0, 64, 191, 255}));
}

TEST(GreyResample, DownscalingSamplesBetweenPixels) {
  // Samples at 0.5 and 2.5: (0 + 100) / 2 = 50, (200 + 255) / 2 = 227.5, halves up.
  EXPECT_EQ(resample_grey(Bytes{0, 100, 200, 255}, 4, 1, 2, 1), (Bytes{50, 228}));
}

TEST(GreyResample, BothWaysAtOnceAndTheSameSizeUnchanged) {
  // 2x2 to 1x1 samples the middle: the mean of the four.
  EXPECT_EQ(resample_grey(Bytes{0, 100, 100, 200}, 2, 2, 1, 1), (Bytes{100}));
  const Bytes map = {1, 2, 3, 4, 5, 6};
  EXPECT_EQ(resample_grey(map, 3, 2, 3, 2), map);
}

TEST(GreyResample, ABadSizeIsRefused) {
  EXPECT_THROW(resample_grey(Bytes{1, 2, 3}, 2, 2, 4, 4), std::invalid_argument);
  EXPECT_THROW(resample_grey(Bytes{1}, 1, 1, 0, 4), std::invalid_argument);
}

}  // namespace
}  // namespace l2
