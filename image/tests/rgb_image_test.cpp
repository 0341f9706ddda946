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

// Every pixel of a rectangle and none outside it, for colours and greys, whole rows and parts,
// clipped on every side.
TEST(RgbImage, FillRectWritesExactlyTheRectangle) {
  const Rgb before{7, 8, 9};
  const Rgb colours[] = {{200, 100, 50}, {60, 60, 60}, {0, 0, 0}};
  struct Rect {
    int x, y, w, h;
  };
  const Rect rects[] = {{0, 0, 7, 5}, {2, 1, 3, 3}, {-3, -2, 5, 4}, {4, 3, 10, 10},
                        {0, 2, 7, 1}, {6, 4, 1, 1}, {1, 1, 0, 3},   {-9, 0, 3, 5}};
  for (const Rgb c : colours) {
    for (const Rect r : rects) {
      RgbImage img(7, 5, before);
      img.fill_rect(r.x, r.y, r.w, r.h, c);
      for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 7; ++x) {
          const bool inside = x >= r.x && x < r.x + r.w && y >= r.y && y < r.y + r.h;
          ASSERT_EQ(img.at(x, y), inside ? c : before) << "pixel " << x << "," << y << " of " << r.x
                                                       << "," << r.y << " " << r.w << "x" << r.h;
        }
      }
    }
  }
}

}  // namespace
}  // namespace l2
