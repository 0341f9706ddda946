#include <gtest/gtest.h>

#include "display_tile.hpp"
#include "image/rgb_image.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "tilelayout/frame_headers.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

StripHeader header_at(const RgbImage& fb, int x, int y) {
  const std::uint8_t* p = fb.row(y).data() + x * 3;
  const auto h = decode(header_value(p, p + 3));
  EXPECT_TRUE(h.has_value()) << "bad check bits at " << x << "," << y;
  return h.value_or(StripHeader{StripOp::Ext, false, 0, 0, 0, 0});
}

constexpr Rgb kPaint{7, 8, 9};

// W = 20: row 0 holds A (5x3, display 2 at 10,100) at gap 0 and B (4x1, display 5 at 0,7) at
// gap 7; 7+2+4 = 13 leaves 7 pixels for END. Row 1 (y = 3) holds C (18x2), which fills it.
struct Fixture {
  PipeserverPlan plan = pack_tiles(
      0, 20, 8,
      {display_tile(2, 10, 100, 5, 3), display_tile(5, 0, 7, 4, 1), display_tile(1, 3, 4, 18, 2)});
  RgbImage fb{20, 8, kPaint};
};

TEST(DrawHeaders, CopyWhileTheTileLastsThenSkipThenEnd) {
  Fixture f;
  draw_headers(f.plan, true, f.fb);
  for (int r = 0; r < 3; ++r) {
    EXPECT_EQ(header_at(f.fb, 0, r), StripHeader::copy(true, 2, 10, 100 + r, 5)) << r;
    EXPECT_EQ(header_at(f.fb, 7, r),
              r == 0 ? StripHeader::copy(true, 5, 0, 7, 4) : StripHeader::skip(true, 4))
        << r;
    EXPECT_EQ(header_at(f.fb, 13, r), StripHeader::end()) << r;
  }
  for (int r = 0; r < 2; ++r) {
    EXPECT_EQ(header_at(f.fb, 0, 3 + r), StripHeader::copy(true, 1, 3, 4 + r, 18)) << r;
  }
}

TEST(DrawHeaders, TouchesOnlyHeaderPixels) {
  Fixture f;
  draw_headers(f.plan, false, f.fb);
  int changed = 0;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 20; ++x) changed += f.fb.at(x, y) != kPaint;
  }
  // Rows 0-2: three headers of two pixels; rows 3-4: one header. Some header pixels could equal
  // kPaint by chance; these do not.
  EXPECT_EQ(changed, 3 * 3 * 2 + 2 * 2);
  EXPECT_EQ(f.fb.at(2, 0), kPaint);
  EXPECT_EQ(f.fb.at(0, 5), kPaint);
}

TEST(DrawHeaders, ParsedScanlinesRouteEveryTileRow) {
  Fixture f;
  clear_outside_tiles(f.plan, f.fb);
  draw_headers(f.plan, true, f.fb);
  std::vector<std::string> seen;
  StripErrorCounts errors;
  for (int y = 0; y < 8; ++y) {
    parse_scanline(f.fb.row(y).data(), 20, 3, errors, [&](const ParsedStrip& s) {
      seen.push_back(std::to_string(y) + ":" + to_string(s.header) + "@" +
                     std::to_string(s.source_x));
    });
  }
  EXPECT_EQ(errors.total(), 0u);
  EXPECT_EQ(seen, (std::vector<std::string>{
                      "0:COPY f=1 d=2 x=10 y=100 w=5@2", "0:COPY f=1 d=5 x=0 y=7 w=4@9",
                      "1:COPY f=1 d=2 x=10 y=101 w=5@2", "1:SKIP f=1 d=0 x=0 y=0 w=4@9",
                      "2:COPY f=1 d=2 x=10 y=102 w=5@2", "2:SKIP f=1 d=0 x=0 y=0 w=4@9",
                      "3:COPY f=1 d=1 x=3 y=4 w=18@2", "4:COPY f=1 d=1 x=3 y=5 w=18@2"}));
}

TEST(DrawHeaders, OnePixelLeftGetsNoEnd) {
  // 2 + 7 = 9 of W = 10: one pixel remains, too few for a header; it stays untouched.
  const PipeserverPlan plan = pack_tiles(0, 10, 1, {display_tile(0, 0, 0, 7, 1)});
  RgbImage fb(10, 1, kPaint);
  draw_headers(plan, false, fb);
  EXPECT_EQ(fb.at(9, 0), kPaint);
  EXPECT_EQ(header_at(fb, 0, 0), StripHeader::copy(false, 0, 0, 0, 7));
}

TEST(DrawHeaders, RejectsAFramebufferOfTheWrongSize) {
  Fixture f;
  RgbImage small(10, 8);
  EXPECT_THROW(draw_headers(f.plan, false, small), LayoutError);
}

TEST(FrameHeaders, DrawsOneScanlineAndNoOther) {
  Fixture f;
  const FrameHeaders headers(f.plan, true);
  headers.draw_row(1, f.fb.row(1));
  EXPECT_EQ(header_at(f.fb, 0, 1), StripHeader::copy(true, 2, 10, 101, 5));
  EXPECT_EQ(header_at(f.fb, 7, 1), StripHeader::skip(true, 4));
  EXPECT_EQ(header_at(f.fb, 13, 1), StripHeader::end());
  int changed = 0;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 20; ++x) changed += f.fb.at(x, y) != kPaint;
  }
  EXPECT_EQ(changed, 3 * 2);  // three headers of scanline 1, nothing else
}

TEST(FrameHeaders, ScanlinesBelowTheLastRowHaveNone) {
  Fixture f;
  const FrameHeaders headers(f.plan, false);
  for (int y = 5; y < 8; ++y) headers.draw_row(y, f.fb.row(y));
  for (int y = 5; y < 8; ++y) {
    for (int x = 0; x < 20; ++x) ASSERT_EQ(f.fb.at(x, y), kPaint) << x << "," << y;
  }
}

TEST(FrameHeaders, RefusesAShortScanlineOrOneOutsideTheFramebuffer) {
  Fixture f;
  const FrameHeaders headers(f.plan, false);
  std::vector<std::uint8_t> short_row(59);
  try {
    headers.draw_row(0, short_row);
    FAIL() << "expected a throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "FrameHeaders: scanline 0 of 59 bytes, the framebuffer is 20x8");
  }
  EXPECT_THROW(headers.draw_row(8, f.fb.row(7)), std::invalid_argument);
  EXPECT_THROW(headers.draw_row(-1, f.fb.row(0)), std::invalid_argument);
}

TEST(ClearOutsideTiles, BlacksEverythingButTilePixelsAndGaps) {
  Fixture f;
  clear_outside_tiles(f.plan, f.fb);
  int painted = 0;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 20; ++x) painted += f.fb.at(x, y) == kPaint;
  }
  // Kept: A 5x3 + its gap 2x3, B 4x1 + gap 2x3, C 18x2 + gap 2x2.
  EXPECT_EQ(painted, 15 + 6 + 4 + 6 + 36 + 4);
  EXPECT_EQ(f.fb.at(9, 1), Rgb{});   // below B
  EXPECT_EQ(f.fb.at(15, 0), Rgb{});  // after the END
  EXPECT_EQ(f.fb.at(0, 5), Rgb{});   // below the last row
}

}  // namespace
}  // namespace l2
