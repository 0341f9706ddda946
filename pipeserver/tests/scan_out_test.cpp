#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "header_at.hpp"
#include "image/rgb_image.hpp"
#include "pipeserver/scan_out.hpp"
#include "strip_headers/strip_header.hpp"
#include "tilelayout/frame_headers.hpp"

namespace l2 {
namespace {

TEST(ScanOut, FlipsRowsAndDropsAlpha) {
  // 5 x 2 RGBA, GL order: row 0 is the bottom. Width 5 exercises the 4-pixel loop and the tail.
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 5; ++x)
      rgba.insert(rgba.end(),
                  {static_cast<std::uint8_t>(10 * x + y), static_cast<std::uint8_t>(100 + y),
                   static_cast<std::uint8_t>(200 + x), 77});
  std::vector<std::uint8_t> rgb(5 * 2 * 3, 0xEE);
  scan_out(rgba.data(), 5, 2, rgb);
  const std::vector<std::uint8_t> expected{
      1, 101, 200, 11, 101, 201, 21, 101, 202, 31, 101, 203, 41, 101, 204,  // GL row 1 = top
      0, 100, 200, 10, 100, 201, 20, 100, 202, 30, 100, 203, 40, 100, 204};
  EXPECT_EQ(rgb, expected);
}

TEST(ScanOut, WideRowsTakeTheVectorPathAndTheTail) {
  // 37 pixels: two 16-pixel blocks and a 5-pixel tail. Every byte distinct within a row.
  const int w = 37, h = 3;
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w * h * 4));
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(i * 7 + 3);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w * h * 3) + 16, 0xEE);
  scan_out(rgba.data(), w, h, rgb);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const auto want = rgba[static_cast<std::size_t>(((h - 1 - y) * w + x) * 4 + c)];
        ASSERT_EQ(rgb[static_cast<std::size_t>((y * w + x) * 3 + c)], want) << x << "," << y;
      }
  for (std::size_t i = static_cast<std::size_t>(w * h * 3); i < rgb.size(); ++i)
    EXPECT_EQ(rgb[i], 0xEE);
}

TEST(ScanOut, WritesNothingPastTheFrame) {
  std::vector<std::uint8_t> rgba(3 * 3 * 4, 9);
  std::vector<std::uint8_t> rgb(3 * 3 * 3 + 4, 0xEE);
  scan_out(rgba.data(), 3, 3, std::span(rgb).first(27));
  for (std::size_t i = 27; i < rgb.size(); ++i) EXPECT_EQ(rgb[i], 0xEE);
}

TEST(ScanOut, RefusesASmallDestination) {
  std::vector<std::uint8_t> rgba(4 * 2 * 4), rgb(4 * 2 * 3 - 1);
  try {
    scan_out(rgba.data(), 4, 2, rgb);
    FAIL() << "expected a throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "scan_out: destination holds 23 bytes, 4x2 RGB needs 24");
  }
}

// A 40 x 6 framebuffer: tiles 9x4 (display 1 at 20,30) and 17x2 (display 0 at 0,0) side by
// side, 2 + 9 + 2 + 17 = 30, END at 30.
PipeserverPlan two_tile_plan() {
  DisplayTile a, b;
  a.display = 1, a.on_display = {20, 30, 9, 4};
  b.display = 0, b.on_display = {0, 0, 17, 2};
  a.on_canvas = a.on_display, b.on_canvas = b.on_display;
  return pack_tiles(0, 40, 6, {a, b});
}

std::vector<std::uint8_t> numbered_rgba(int w, int h) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w * h * 4));
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(i * 5 + 1);
  return rgba;
}

using test::header_at;

TEST(ScanOutWithHeaders, EqualsScanOutThenDrawHeaders) {
  const PipeserverPlan plan = two_tile_plan();
  const auto rgba = numbered_rgba(40, 6);
  RgbImage fused(40, 6), separate(40, 6);
  scan_out(rgba.data(), 40, 6, fused.bytes(), FrameHeaders(plan, true));
  scan_out(rgba.data(), 40, 6, separate.bytes());
  const RgbImage plain = separate;
  draw_headers(plan, true, separate);
  EXPECT_TRUE(fused.bytes().size() == separate.bytes().size() &&
              std::equal(fused.bytes().begin(), fused.bytes().end(), separate.bytes().begin()));
  // The headers are there (the numbered pixels are not valid headers) and the rest is the plain
  // scan-out: row 3 holds COPY for tile a, SKIP below tile b, END.
  EXPECT_EQ(header_at(fused, 0, 3), StripHeader::copy(true, 1, 20, 33, 9));
  EXPECT_EQ(header_at(fused, 11, 3), StripHeader::skip(true, 17));
  EXPECT_EQ(header_at(fused, 30, 3), StripHeader::end());
  EXPECT_EQ(fused.at(5, 3), plain.at(5, 3));
  EXPECT_EQ(fused.at(32, 3), plain.at(32, 3));
}

TEST(ScanOutWithHeaders, RefusesHeadersOfAnotherFramebuffer) {
  const auto rgba = numbered_rgba(40, 6);
  RgbImage fb(40, 5);
  try {
    scan_out(rgba.data(), 40, 5, fb.bytes(), FrameHeaders(two_tile_plan(), false));
    FAIL() << "expected a throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "scan_out: headers for 40x6, the frame is 40x5");
  }
}

}  // namespace
}  // namespace l2
