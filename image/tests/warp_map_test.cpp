// A picture through a geometry warp (image/warp_map.hpp): normalised positions taken to 1/256
// pixel, and the bilinear rule in integers; each expected byte worked out here from the rule as
// docs/wall-file.md states it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "image/warp_map.hpp"

namespace l2 {
namespace {

// Every output pixel's normalised position from `at(x, y)`, which returns it in pixels (pixel
// centres at integers, as the map holds them).
template <class At>
std::vector<float> positions(int w, int h, At at) {
  std::vector<float> p;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const auto [sx, sy] = at(x, y);
      p.push_back(static_cast<float>((sx + 0.5) / w));
      p.push_back(static_cast<float>((sy + 0.5) / h));
    }
  }
  return p;
}

// A picture whose bytes differ everywhere: pixel (x, y) is (10x + y, 3y + 1, 200 - 7x).
RgbImage numbered(int w, int h) {
  RgbImage in(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      in.set(x, y,
             {static_cast<std::uint8_t>(10 * x + y), static_cast<std::uint8_t>(3 * y + 1),
              static_cast<std::uint8_t>(200 - 7 * x)});
  return in;
}

TEST(WarpMap, PixelCentresGiveTheSameBytes) {
  const int w = 13, h = 7;
  const WarpMap m = warp_map_from_positions(
      w, h, w, h, positions(w, h, [](int x, int y) { return std::pair(x, y); }));
  EXPECT_TRUE(is_identity(m));
  EXPECT_EQ(m.source[2 * (3 * w + 5)], 5 * 256);
  EXPECT_EQ(m.source[2 * (3 * w + 5) + 1], 3 * 256);
  const RgbImage in = numbered(w, h);
  RgbImage out;
  apply_warp(m, in, out);
  EXPECT_TRUE(out == in);
}

// The identity at a display's largest size still lands on whole pixels: float positions of
// centres, taken through double, round back to exactly x * 256.
TEST(WarpMap, CentresOfAWideDisplayRoundToWholePixels) {
  const int w = 4095, h = 1;
  const WarpMap m = warp_map_from_positions(
      w, h, w, h, positions(w, h, [](int x, int y) { return std::pair(x, y); }));
  EXPECT_TRUE(is_identity(m));
}

TEST(WarpMap, AHalfPixelShiftAveragesNeighboursRoundingHalvesUp) {
  const int w = 4, h = 2;
  // Each output pixel half a pixel to the right of its own: between x and x + 1.
  const WarpMap m = warp_map_from_positions(
      w, h, w, h, positions(w, h, [](int x, int y) { return std::pair(x + 0.5, double(y)); }));
  EXPECT_EQ(m.source[0], 128);
  // The last column's position is beyond the last centre: clamped to it.
  EXPECT_EQ(m.source[2 * 3], 3 * 256);
  RgbImage in(w, h);
  in.set(0, 0, {10, 0, 255});
  in.set(1, 0, {13, 1, 0});
  in.set(2, 0, {200, 100, 50});
  in.set(3, 0, {7, 8, 9});
  RgbImage out;
  apply_warp(m, in, out);
  // (a * 128 + b * 128) * 256 + 32768 >> 16 = (a + b + 1) / 2, rounded down.
  EXPECT_EQ(out.at(0, 0), (Rgb{12, 1, 128}));   // 11.5 -> 12, 0.5 -> 1, 127.5 -> 128
  EXPECT_EQ(out.at(1, 0), (Rgb{107, 51, 25}));  // 106.5, 50.5, 25
  EXPECT_EQ(out.at(2, 0), (Rgb{104, 54, 30}));  // 103.5, 54, 29.5
  EXPECT_EQ(out.at(3, 0), (Rgb{7, 8, 9}));      // clamped: the last pixel itself
  EXPECT_EQ(out.at(0, 1), (Rgb{0, 0, 0}));      // the second row is black and stays so
}

TEST(WarpMap, AQuarterPixelDownAndRightMixesFourPixels) {
  const int w = 2, h = 2;
  const WarpMap m = warp_map_from_positions(
      w, h, w, h, positions(w, h, [](int, int) { return std::pair(0.25, 0.75); }));
  EXPECT_EQ(m.source[0], 64);
  EXPECT_EQ(m.source[1], 192);
  RgbImage in(w, h);
  in.set(0, 0, {100, 0, 0});
  in.set(1, 0, {200, 0, 0});
  in.set(0, 1, {0, 40, 0});
  in.set(1, 1, {0, 80, 255});
  RgbImage out;
  apply_warp(m, in, out);
  // r: top 100 * 192 + 200 * 64 = 32000, bottom 0: 32000 * 64 = 2048000; + 32768 >> 16 = 31.
  // g: bottom 40 * 192 + 80 * 64 = 12800; * 192 = 2457600; + 32768 >> 16 = 38.
  // b: bottom 255 * 64 = 16320; * 192 = 3133440; + 32768 >> 16 = 48.
  EXPECT_EQ(out.at(1, 1), (Rgb{31, 38, 48}));
}

TEST(WarpMap, AMirrorSwapsColumns) {
  const int w = 5, h = 3;
  const WarpMap m = warp_map_from_positions(
      w, h, w, h, positions(w, h, [&](int x, int y) { return std::pair(w - 1 - x, y); }));
  EXPECT_FALSE(is_identity(m));
  const RgbImage in = numbered(w, h);
  RgbImage out;
  apply_warp(m, in, out);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) EXPECT_EQ(out.at(x, y), in.at(w - 1 - x, y)) << x << "," << y;
}

TEST(WarpMap, NanAndPositionsOffTheFrameShowBlack) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // 5 pixels: NaN x, NaN y, x below 0, y above 1, and exactly 1 (the far corner: on the frame).
  const std::vector<float> p{nan, 0.5f, 0.5f, nan, -0.01f, 0.5f, 0.5f, 1.01f, 1.0f, 1.0f};
  const WarpMap m = warp_map_from_positions(5, 1, 5, 1, p);
  RgbImage in(5, 1, Rgb{9, 9, 9});
  in.set(4, 0, {1, 2, 3});
  RgbImage out(5, 1, Rgb{255, 255, 255});
  apply_warp(m, in, out);
  for (int x = 0; x < 4; ++x) EXPECT_EQ(out.at(x, 0), (Rgb{0, 0, 0})) << x;
  EXPECT_EQ(out.at(4, 0), (Rgb{1, 2, 3}));
}

// A 2x2 grid over a 5x3 display: its points on the corner pixels' centres, the pixels between
// mixed bilinearly. The corners shift the frame right by a quarter of its width at the bottom
// only: a keystone.
TEST(WarpMap, ACoarseGridIsSpreadOverThePixelCentres) {
  const std::vector<float> grid{0.0f,  0.0f, 0.5f,  0.0f,   // top: x 0 .. 0.5
                                0.25f, 1.0f, 0.75f, 1.0f};  // bottom: x 0.25 .. 0.75
  const WarpMap m = warp_map_from_positions(5, 3, 2, 2, grid);
  // Pixel (x, y): x position (x / 4) * 0.5 + (y / 2) * 0.25, y position y / 2; in 1/256 pixel,
  // p * 5 * 256 - 128 and q * 3 * 256 - 128, clamped to 0..4*256 and 0..2*256.
  const auto expect = [&](int x, int y, int sx, int sy) {
    const std::size_t i = 2 * (static_cast<std::size_t>(y) * 5 + x);
    EXPECT_EQ(m.source[i], sx) << x << "," << y;
    EXPECT_EQ(m.source[i + 1], sy) << x << "," << y;
  };
  expect(0, 0, 0, 0);      // (0, 0): -128 clamped to 0
  expect(4, 0, 512, 0);    // (0.5, 0): 640 - 128
  expect(2, 1, 352, 256);  // (0.375, 0.5): 480 - 128; 384 - 128
  expect(0, 2, 192, 512);  // (0.25, 1): 320 - 128; 768 - 128 = 640 clamped to 512
  expect(3, 2, 672, 512);  // (0.625, 1): 800 - 128
}

TEST(WarpMap, WrongSizesAreRefused) {
  EXPECT_THROW(warp_map_from_positions(2, 2, 2, 2, std::vector<float>(7)), std::invalid_argument);
  EXPECT_THROW(warp_map_from_positions(2, 2, 3, 2, std::vector<float>(12)), std::invalid_argument);
  EXPECT_THROW(warp_map_from_positions(3, 2, 1, 2, std::vector<float>(4)), std::invalid_argument);
  const WarpMap m =
      warp_map_from_positions(2, 1, 2, 1, std::vector<float>{0.25f, 0.5f, 0.75f, 0.5f});
  RgbImage out;
  EXPECT_THROW(apply_warp(m, RgbImage(3, 1), out), std::invalid_argument);
  RgbImage same(2, 1);
  EXPECT_THROW(apply_warp(m, same, same), std::invalid_argument);
}

}  // namespace
}  // namespace l2
