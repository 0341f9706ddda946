// The pictures and counts a golden mismatch is reported with.
#include <gtest/gtest.h>

#include "display_compare.hpp"
#include "golden/golden_entry.hpp"

namespace l2 {
namespace {

RgbImage gradient(int w, int h) {
  RgbImage image(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      image.set(x, y, Rgb{static_cast<std::uint8_t>(x * 6), static_cast<std::uint8_t>(y * 5), 200});
    }
  }
  return image;
}

TEST(CompareDisplays, FindsTheLargestDifferenceAndCountsThoseBeyondOneLevel) {
  const RgbImage a = gradient(40, 30);
  RgbImage b = a;
  b.set(3, 4, Rgb{static_cast<std::uint8_t>(a.at(3, 4).r + 1), a.at(3, 4).g, 200});  // by one
  b.set(20, 10, Rgb{a.at(20, 10).r, a.at(20, 10).g, 100});                           // by 100
  b.set(30, 20, Rgb{a.at(30, 20).r, a.at(30, 20).g, 190});                           // by 10
  const DisplayDiff d = compare_displays(a, b);
  EXPECT_EQ(d.differing_pixels, 3u);
  EXPECT_EQ(d.beyond_one, 2u);
  EXPECT_EQ(d.largest, 100);
  EXPECT_EQ(d.largest_x, 20);
  EXPECT_EQ(d.largest_y, 10);
  EXPECT_EQ(describe_diff(d),
            "3 pixels differ (2 by more than one level), largest difference 100 at (20, 10)");
}

TEST(HighlightDifferences, OnePixelIsMagentaInAYellowSquareOnADimmedCopy) {
  const RgbImage expected = gradient(40, 30);
  RgbImage actual = expected;
  actual.set(12, 15, Rgb{0, 0, 0});
  const RgbImage p = highlight_differences(expected, actual);
  EXPECT_EQ(p.at(12, 15), kDiffPixel);
  EXPECT_EQ(p.at(12 + 6, 15), kDiffMarker);  // the square's sides are 6 pixels away
  EXPECT_EQ(p.at(12 - 6, 15 - 6), kDiffMarker);
  EXPECT_EQ(p.at(12 + 3, 15), (Rgb{15 * 6 / 4, 15 * 5 / 4, 50}));
  EXPECT_EQ(p.at(0, 0), (Rgb{0, 0, 50}));
  EXPECT_EQ(p.at(39, 29), (Rgb{39 * 6 / 4, 29 * 5 / 4, 50}));
}

TEST(HighlightDifferences, ManyDifferencesAreNotMarked) {
  const RgbImage expected(100, 100, Rgb{40, 40, 40});
  const RgbImage actual(100, 100, Rgb{41, 40, 40});
  const RgbImage p = highlight_differences(expected, actual);
  EXPECT_GT(100u * 100u, kMarkedPixels);
  for (const auto& [x, y] : {std::pair{0, 0}, std::pair{50, 50}, std::pair{99, 99}}) {
    EXPECT_EQ(p.at(x, y), kDiffPixel);
  }
}

TEST(HighlightDifferences, DifferentSizesGetAMagentaBorder) {
  const RgbImage p = highlight_differences(RgbImage(10, 10), RgbImage(20, 12, Rgb{80, 80, 80}));
  EXPECT_EQ(p.width(), 20);
  EXPECT_EQ(p.at(0, 5), kDiffPixel);
  EXPECT_EQ(p.at(19, 11), kDiffPixel);
  EXPECT_EQ(p.at(10, 6), (Rgb{20, 20, 20}));
}

// The reassembly tolerance on 10000 pixels: 1 may differ (0.01 %), none by more than one level.
TEST(CompareSets, ToleranceCountsOverAllDisplaysTogether) {
  const std::vector<RgbImage> expected{RgbImage(100, 50), RgbImage(100, 50)};
  std::vector<RgbImage> actual = expected;
  const Tolerance t = Tolerance::reassembly();
  EXPECT_TRUE(compare_sets(expected, actual, t).passed);
  actual[1].set(7, 7, Rgb{1, 0, 0});
  SetComparison c = compare_sets(expected, actual, t);
  EXPECT_TRUE(c.passed);
  EXPECT_EQ(c.pixels, 10000u);
  EXPECT_EQ(c.differing, 1u);
  EXPECT_FALSE(compare_sets(expected, actual, Tolerance{}).passed);  // exact
  actual[1].set(7, 7, Rgb{2, 0, 0});
  EXPECT_FALSE(compare_sets(expected, actual, t).passed);  // beyond one level
  actual[1].set(7, 7, Rgb{1, 0, 0});
  actual[0].set(0, 0, Rgb{0, 1, 0});
  c = compare_sets(expected, actual, t);
  EXPECT_FALSE(c.passed);  // two differ
  EXPECT_EQ(c.displays[0].differing_pixels, 1u);
  EXPECT_EQ(c.displays[1].differing_pixels, 1u);
}

TEST(CompareSets, ADifferentSizeIsNeverWithinTolerance) {
  const Tolerance loose{false, 100, 100};
  EXPECT_FALSE(compare_sets({RgbImage(10, 10)}, {RgbImage(10, 11)}, loose).passed);
}

}  // namespace
}  // namespace l2
