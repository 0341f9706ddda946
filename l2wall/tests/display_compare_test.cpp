#include "display_compare.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(CompareDisplays, IdenticalPicturesHaveABlackDiff) {
  RgbImage a(4, 3, Rgb{10, 20, 30});
  const DisplayDiff d = compare_displays(a, a);
  EXPECT_TRUE(d.identical());
  EXPECT_EQ(d.picture.at(3, 2), (Rgb{0, 0, 0}));
}

TEST(CompareDisplays, CountsAndMarksEveryDifferingPixel) {
  RgbImage a(4, 3, Rgb{10, 20, 30});
  RgbImage b = a;
  b.set(1, 1, Rgb{11, 20, 30});   // one step in red
  b.set(3, 2, Rgb{10, 20, 130});  // 100 in blue
  const DisplayDiff d = compare_displays(a, b);
  EXPECT_EQ(d.differing_pixels, 2u);
  EXPECT_EQ(d.picture.at(1, 1), (Rgb{64, 0, 0}));
  EXPECT_EQ(d.picture.at(3, 2), (Rgb{0, 0, 100}));
  EXPECT_EQ(d.picture.at(0, 0), (Rgb{0, 0, 0}));
}

TEST(CompareDisplays, DifferentSizesDifferEverywhere) {
  const DisplayDiff d = compare_displays(RgbImage(4, 3), RgbImage(5, 3));
  EXPECT_EQ(d.differing_pixels, 15u);
}

}  // namespace
}  // namespace l2
