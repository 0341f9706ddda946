#include "displays/bitmap_font.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

constexpr Rgb kInk{255, 255, 255};

// The glyph as '#'/'.' rows read back from the image.
std::vector<std::string> rows_of(const RgbImage& image) {
  std::vector<std::string> rows;
  for (int y = 0; y < image.height(); ++y) {
    std::string row;
    for (int x = 0; x < image.width(); ++x) row += image.at(x, y) == kInk ? '#' : '.';
    rows.push_back(row);
  }
  return rows;
}

TEST(BitmapFont, DrawsTheOneGlyph) {
  RgbImage image(5, 7);
  draw_text(image, 0, 0, "1", kInk, 1);
  EXPECT_EQ(rows_of(image), (std::vector<std::string>{"..#..", ".##..", "..#..", "..#..", "..#..",
                                                      "..#..", ".###."}));
}

TEST(BitmapFont, LowerCaseDrawsAsCapitalsAndScaleDoublesPixels) {
  RgbImage lower(12, 14), upper(12, 14);
  draw_text(lower, 0, 0, "f", kInk, 2);
  draw_text(upper, 0, 0, "F", kInk, 2);
  EXPECT_EQ(lower, upper);
  EXPECT_EQ(lower.at(0, 0), kInk);
  EXPECT_EQ(lower.at(9, 1), kInk);    // top bar, 5 font pixels wide -> x 0..9
  EXPECT_EQ(lower.at(10, 0), Rgb{});  // the advance gap
}

TEST(BitmapFont, WidthAndClippingAtTheEdge) {
  EXPECT_EQ(text_width("", 1), 0);
  EXPECT_EQ(text_width("ab", 1), 11);
  EXPECT_EQ(text_width("ab", 2), 22);
  RgbImage image(4, 4);
  draw_text(image, 2, 2, "88888", kInk, 3);  // mostly outside: must not write out of bounds
  EXPECT_EQ(image.at(0, 0), Rgb{});
}

}  // namespace
}  // namespace l2
