#include "image/legend.hpp"

#include <gtest/gtest.h>

#include "image/label_text.hpp"

namespace l2 {
namespace {

TEST(Legend, LinesGoBelowThePictureWithTheirSwatches) {
  const RgbImage picture(20, 10, Rgb{9, 9, 9});
  const std::vector<LegendEntry> entries{{"red", {255, 0, 0}}, {"text only", {1, 2, 3}, false}};
  const RgbImage out = with_legend(picture, entries);
  // Scale 1: 2 pixels of space, lines of 7 + 3 pixels, 2 pixels below; as wide as the longest
  // line, which starts after a swatch of 7 and 5 pixels of space.
  EXPECT_EQ(out.height(), 10 + 2 + 2 * 10 + 2);
  EXPECT_EQ(out.width(), 12 + text_width("text only", 1) + 2);
  EXPECT_EQ(out.at(19, 9), (Rgb{9, 9, 9}));    // the picture, unchanged
  EXPECT_EQ(out.at(2, 12), (Rgb{255, 0, 0}));  // the first swatch
  EXPECT_EQ(out.at(8, 18), (Rgb{255, 0, 0}));  // its last pixel
  EXPECT_EQ(out.at(2, 22), (Rgb{0, 0, 0}));    // no swatch on the second line
  EXPECT_EQ(legend_scale(640), 1);
  EXPECT_EQ(legend_scale(1300), 2);
}

}  // namespace
}  // namespace l2
