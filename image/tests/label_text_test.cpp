#include "image/label_text.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

constexpr Rgb kInk{255, 255, 255};

struct Inked {
  int pixels = 0, full = 0;        // pixels touched, pixels fully inked
  int left = 1 << 30, right = -1;  // columns touched
  int top = 1 << 30, bottom = -1;  // rows touched
  bool only_grey = true;           // every pixel a grey between black and the ink
};

Inked inked(const RgbImage& image) {
  Inked in;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const Rgb c = image.at(x, y);
      if (c.r != c.g || c.g != c.b) in.only_grey = false;
      if (c == Rgb{}) continue;
      ++in.pixels;
      if (c == kInk) ++in.full;
      in.left = std::min(in.left, x), in.right = std::max(in.right, x);
      in.top = std::min(in.top, y), in.bottom = std::max(in.bottom, y);
    }
  }
  return in;
}

TEST(LabelText, CapitalsAreTheirHeightTallFromTheTopGiven) {
  RgbImage image(60, 40);
  draw_text(image, 10, 5, "HE", kInk, 2);  // capitals 14 pixels tall, no descender
  const Inked in = inked(image);
  EXPECT_TRUE(in.only_grey);
  EXPECT_GT(in.full, 20);  // the stems are solid ink
  EXPECT_GE(in.top, 5);
  EXPECT_LE(in.top, 6);
  EXPECT_GE(in.bottom, 5 + 14 - 2);
  EXPECT_LE(in.bottom, 5 + 14);
  EXPECT_GE(in.left, 10);
  EXPECT_LE(in.right, 10 + text_width("HE", 2));
}

TEST(LabelText, WidthGrowsWithTextAndScale) {
  EXPECT_EQ(text_width("", 1), 0);
  // A monospaced font: five characters are five times as wide as one, within rounding.
  const int one = text_width("a", 2), five = text_width("abcde", 2);
  EXPECT_GT(one, 5);
  EXPECT_NEAR(five, 5 * one, 3);
  EXPECT_GT(text_width("ab", 4), text_width("ab", 2));
}

TEST(LabelText, DescendersGoBelowTheCapitals) {
  RgbImage image(40, 30);
  draw_text(image, 0, 0, "gy", kInk, 2);
  EXPECT_GT(inked(image).bottom, 14);
}

TEST(LabelText, ClippedAtTheEdge) {
  RgbImage image(4, 4);
  draw_text(image, 2, 2, "88888", kInk, 3);  // mostly outside: must not write out of bounds
  EXPECT_EQ(image.at(0, 0), Rgb{});
  RgbImage none(4, 4);
  draw_text(none, -100, -100, "x", kInk, 1);
  EXPECT_EQ(inked(none).pixels, 0);
}

}  // namespace
}  // namespace l2
