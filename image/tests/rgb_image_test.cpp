#include "image/rgb_image.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(RgbImage, RowsAreContiguousTopToBottom) {
  RgbImage img(4, 3, {1, 2, 3});
  EXPECT_EQ(img.stride(), 12u);
  img.set(1, 2, {9, 8, 7});
  EXPECT_EQ(img.row(2)[3], 9);
  EXPECT_EQ(img.row(2)[4], 8);
  EXPECT_EQ(img.row(2)[5], 7);
  EXPECT_EQ(img.at(0, 0), (Rgb{1, 2, 3}));
}

TEST(RgbImage, FillRectClipsToTheImage) {
  RgbImage img(4, 4);
  img.fill_rect(-2, 2, 4, 10, {255, 0, 0});
  EXPECT_EQ(img.at(0, 3), (Rgb{255, 0, 0}));
  EXPECT_EQ(img.at(1, 2), (Rgb{255, 0, 0}));
  EXPECT_EQ(img.at(2, 2), (Rgb{}));
  EXPECT_EQ(img.at(0, 1), (Rgb{}));
}

}  // namespace
}  // namespace l2
