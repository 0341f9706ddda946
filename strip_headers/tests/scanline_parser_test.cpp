#include "strip_headers/scanline_parser.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "scanline_row.hpp"

namespace l2 {
namespace {

using testing::counts;
using testing::parse;
using testing::Parsed;
using testing::Row;

class ParserBothLayouts : public ::testing::TestWithParam<int> {};

TEST_P(ParserBothLayouts, WalksCopySkipAndEndInOrder) {
  Row row(40, GetParam());
  row.header(0, StripHeader::copy(true, 3, 100, 7, 10));  // strip at 2..11
  row.header(12, StripHeader::skip(true, 5));             // strip at 14..18
  row.header(19, StripHeader::copy(true, 4, 0, 8, 3));    // strip at 21..23
  row.header(24, StripHeader::end());
  row.header(26, StripHeader::copy(true, 1, 0, 0, 2));  // after END: must not be seen
  const Parsed p = parse(row);
  ASSERT_EQ(p.strips.size(), 3u);
  EXPECT_EQ(p.strips[0].source_x, 2);
  EXPECT_EQ(p.strips[0].length, 10);
  EXPECT_EQ(p.strips[0].header.display, 3);
  EXPECT_EQ(p.strips[0].header.x, 100);
  EXPECT_EQ(p.strips[0].header.y, 7);
  EXPECT_EQ(p.strips[1].header.op, StripOp::Skip);
  EXPECT_EQ(p.strips[1].source_x, 14);
  EXPECT_EQ(p.strips[2].source_x, 21);
  EXPECT_EQ(p.strips[2].length, 3);
  EXPECT_EQ(p.errors, StripErrorCounts{});
}

INSTANTIATE_TEST_SUITE_P(RgbAndRgba, ParserBothLayouts, ::testing::Values(3, 4));

TEST(ScanlineParser, BadCheckDropsTheRestAndCountsOne) {
  Row row(30, 3);
  row.header(0, StripHeader::copy(false, 0, 0, 0, 4));
  row.header(6, encode(StripHeader::copy(false, 0, 4, 0, 4)) ^ 0x10);  // one bit flipped
  row.header(12, StripHeader::copy(false, 0, 8, 0, 4));
  const Parsed p = parse(row);
  EXPECT_EQ(p.strips.size(), 1u);
  EXPECT_EQ(p.errors, counts(1, 0, 0, 0));
}

TEST(ScanlineParser, ZeroWidthCopyOrSkipDropsTheRest) {
  for (StripOp op : {StripOp::Copy, StripOp::Skip}) {
    Row row(30, 3);
    row.header(0, StripHeader::copy(false, 0, 0, 0, 2));
    row.header(4, StripHeader{op, false, 0, 0, 0, 0});
    row.header(6, StripHeader::copy(false, 0, 0, 0, 2));
    const Parsed p = parse(row);
    EXPECT_EQ(p.strips.size(), 1u);
    EXPECT_EQ(p.errors, counts(0, 0, 1, 0));
  }
}

TEST(ScanlineParser, TruncatedStripRoutesWhatExists) {
  Row row(20, 3);
  row.header(0, StripHeader::copy(false, 2, 50, 9, 100));
  const Parsed p = parse(row);
  ASSERT_EQ(p.strips.size(), 1u);
  EXPECT_EQ(p.strips[0].source_x, 2);
  EXPECT_EQ(p.strips[0].length, 18);
  EXPECT_EQ(p.strips[0].header.width, 100);
  EXPECT_EQ(p.errors, counts(0, 0, 0, 1));
}

TEST(ScanlineParser, StripEndingExactlyAtTheRowEndIsNotTruncated) {
  Row row(12, 3);
  row.header(0, StripHeader::copy(false, 0, 0, 0, 10));
  const Parsed p = parse(row);
  ASSERT_EQ(p.strips.size(), 1u);
  EXPECT_EQ(p.errors, StripErrorCounts{});
}

TEST(ScanlineParser, SinglePixelLeftIsNotAHeader) {
  Row row(13, 3);
  row.header(0, StripHeader::copy(false, 0, 0, 0, 10));
  row.bytes[12 * 3] = 0xFF;  // one stray pixel: fewer than two remain, parsing stops
  const Parsed p = parse(row);
  EXPECT_EQ(p.strips.size(), 1u);
  EXPECT_EQ(p.errors, StripErrorCounts{});
}

TEST(ScanlineParser, BlackRowIsOneEndAndNothingElse) {
  Row row(1280, 3);
  const Parsed p = parse(row);
  EXPECT_TRUE(p.strips.empty());
  EXPECT_EQ(p.errors, StripErrorCounts{});
}

TEST(ScanlineParser, RandomBytesNeverLeaveTheRow) {
  // Run under ASan: every strip handed over must lie inside the row, whatever the bytes.
  std::mt19937_64 rng(1234);
  std::uniform_int_distribution<int> width_dist(0, 300);
  for (int i = 0; i < 20000; ++i) {
    const int bpp = (i % 2) ? 3 : 4;
    const int width = width_dist(rng);
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(width) * bpp);
    for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
    // Seed valid headers now and then so long strip chains are exercised too.
    for (int x = 0; x + 1 < width; x += 7) {
      if (rng() % 3 == 0) {
        write_header_pixels(encode(StripHeader::copy(false, 0, 0, 0, 1 + rng() % 8)),
                            &bytes[x * bpp], bpp);
      }
    }
    StripErrorCounts errors;
    // Heap copy of exactly the row so ASan catches any over-read.
    auto row = std::make_unique<std::uint8_t[]>(bytes.size() + 0);
    std::copy(bytes.begin(), bytes.end(), row.get());
    long pixels = 0;
    parse_scanline(row.get(), width, bpp, errors, [&](const ParsedStrip& s) {
      ASSERT_GE(s.source_x, 2);
      ASSERT_GE(s.length, 0);
      ASSERT_LE(s.source_x + s.length, width);
      pixels += s.length;
    });
    ASSERT_LE(pixels, width);
  }
}

TEST(ScanlineParser, ErrorCountsAddUp) {
  StripErrorCounts a = counts(1, 2, 3, 4);
  a.missing_display = 5;
  a.clips = 6;
  StripErrorCounts b = a;
  b += a;
  EXPECT_EQ(b.total(), 42u);
  EXPECT_EQ(b.clips, 12u);
}

}  // namespace
}  // namespace l2
