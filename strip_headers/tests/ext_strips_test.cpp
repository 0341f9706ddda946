// Spec §7: KEY and DEPTH strips through the scanline parser, and every error row of §7's table
// in the table's order. Expected columns are worked out by hand from the packing rules.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "scanline_row.hpp"
#include "strip_headers/scanline_parser.hpp"

namespace l2 {
namespace {

using testing::counts;
using testing::parse;
using testing::Parsed;
using testing::Row;

StripHeader ext(bool frame, int display, int x, int y, int width) {
  StripHeader h = StripHeader::copy(frame, display, x, y, width);
  h.op = StripOp::Ext;
  return h;
}

const std::uint64_t kKeyGreen = 0x1000FF000019;  // §7 vectors
const std::uint64_t kDepth = 0x200000000064;
const std::uint64_t kKind3 = 0x300000000056;

class ExtBothLayouts : public ::testing::TestWithParam<int> {};

TEST_P(ExtBothLayouts, KeyAndDepthStripsYieldTheirPayloadSpans) {
  Row row(40, GetParam());
  row.ext(0, ext(true, 3, 100, 7, 5), kKeyGreen);       // word 2..3, colour 4..8
  row.ext(9, ext(true, 4, 0, 8, 6), kDepth);            // word 11..12, colour 13..18, depth 19..24
  row.header(25, StripHeader::copy(true, 1, 2, 3, 3));  // strip 27..29
  row.header(30, StripHeader::end());
  row.header(32, StripHeader::copy(true, 1, 0, 0, 2));  // after END: must not be seen
  const Parsed p = parse(row);
  ASSERT_EQ(p.strips.size(), 3u);
  const ParsedStrip& key = p.strips[0];
  EXPECT_EQ(key.header, ext(true, 3, 100, 7, 5));
  EXPECT_TRUE(key.is(ExtKind::Key));
  EXPECT_EQ(key.extension.key, 0x00FF00u);
  EXPECT_EQ(key.header_x(), 0);
  EXPECT_EQ(key.source_x, 4);
  EXPECT_EQ(key.length, 5);
  EXPECT_EQ(key.next_header_x(), 9);
  const ParsedStrip& depth = p.strips[1];
  EXPECT_TRUE(depth.is(ExtKind::Depth));
  EXPECT_EQ(depth.header.display, 4);
  EXPECT_EQ(depth.header_x(), 9);
  EXPECT_EQ(depth.source_x, 13);
  EXPECT_EQ(depth.length, 6);
  EXPECT_EQ(depth.depth_x(), 19);
  EXPECT_EQ(depth.next_header_x(), 25);
  EXPECT_EQ(p.strips[2].header.op, StripOp::Copy);
  EXPECT_EQ(p.strips[2].header_x(), 25);
  EXPECT_EQ(p.strips[2].source_x, 27);
  EXPECT_EQ(p.errors, StripErrorCounts{});
}

INSTANTIATE_TEST_SUITE_P(RgbAndRgba, ExtBothLayouts, ::testing::Values(3, 4));

// One EXT header at column `at` of a row `width` pixels wide, a valid COPY wherever the strip
// could end, so that a scanline the parser should have dropped shows up as a seen COPY.
struct ExtCase {
  const char* what;
  int width;
  int at;  // the EXT header's column; a SKIP before it fills columns 0..at-1
  StripHeader header;
  std::uint64_t word;
  StripErrorCounts expected;
  int strips;  // handed over, the SKIP included
};

Parsed parse_case(const ExtCase& c) {
  Row row(c.width, 3);
  if (c.at > 0) row.header(0, StripHeader::skip(false, c.at - 2));
  row.header(c.at, c.header);
  if (c.at + 4 <= c.width) row.header(c.at + 2, c.word);  // a word needs two pixels
  for (int x = c.at + 4; x + 1 < c.width && x < c.at + 12; x += 2) {
    row.header(x, StripHeader::copy(false, 0, 0, 0, 1));
  }
  return parse(row);
}

// §7's error table, row by row, and where several apply, the first is the one counted.
const ExtCase kErrorRows[] = {
    {"word does not fit: 2 pixels left", 10, 8, ext(false, 0, 0, 0, 4), kKeyGreen,
     counts(0, 0, 0, 1), 1},
    {"word does not fit: 3 pixels left", 11, 8, ext(false, 0, 0, 0, 4), kKeyGreen,
     counts(0, 0, 0, 1), 1},
    {"word does not fit, and width 0", 10, 8, ext(false, 0, 0, 0, 0), kKeyGreen, counts(0, 0, 0, 1),
     1},
    {"word check mismatch", 40, 0, ext(false, 0, 0, 0, 4), kKeyGreen ^ 0x100, counts(1, 0, 0, 0),
     0},
    {"word check mismatch, unsupported kind and width 0", 40, 0, ext(false, 0, 0, 0, 0), kKind3 ^ 1,
     counts(1, 0, 0, 0), 0},
    {"kind 3", 40, 0, ext(false, 0, 0, 0, 4), kKind3, counts(0, 1, 0, 0), 0},
    {"a black word: kind 0, its check right", 40, 0, ext(false, 0, 0, 0, 4), 0, counts(0, 1, 0, 0),
     0},
    {"kind 15", 40, 0, ext(false, 0, 0, 0, 4), with_extension_check(std::uint64_t{0xF} << 44),
     counts(0, 1, 0, 0), 0},
    {"KEY, bit 43 set", 40, 0, ext(false, 0, 0, 0, 4),
     with_extension_check(kKeyGreen | std::uint64_t{1} << 43), counts(0, 1, 0, 0), 0},
    {"DEPTH, bit 8 set", 40, 0, ext(false, 0, 0, 0, 4), with_extension_check(kDepth | 1 << 8),
     counts(0, 1, 0, 0), 0},
    {"DEPTH with a key", 40, 0, ext(false, 0, 0, 0, 4), with_extension_check(kDepth | 1 << 16),
     counts(0, 1, 0, 0), 0},
    {"kind 3 and width 0", 40, 0, ext(false, 0, 0, 0, 0), kKind3, counts(0, 1, 0, 0), 0},
    {"KEY of width 0", 40, 6, ext(false, 0, 0, 0, 0), kKeyGreen, counts(0, 0, 1, 0), 1},
    {"DEPTH of width 0", 40, 0, ext(false, 0, 0, 0, 0), kDepth, counts(0, 0, 1, 0), 0},
};

TEST(ExtStrips, EachErrorRowIsCountedOnceInTheTablesOrder) {
  for (const ExtCase& c : kErrorRows) {
    const Parsed p = parse_case(c);
    EXPECT_EQ(p.errors, c.expected) << c.what;
    EXPECT_EQ(static_cast<int>(p.strips.size()), c.strips) << c.what;
  }
}

TEST(ExtStrips, KeyPastTheEndRoutesTheColourPixelsThatExist) {
  Row row(20, 3);
  row.ext(0, ext(true, 2, 50, 9, 30), kKeyGreen);  // colour 4..33 of which 4..19 exist
  const Parsed p = parse(row);
  ASSERT_EQ(p.strips.size(), 1u);
  EXPECT_EQ(p.strips[0].source_x, 4);
  EXPECT_EQ(p.strips[0].length, 16);
  // The destination stays whole: the router counts a missing display or a clip besides.
  EXPECT_EQ(p.strips[0].header, ext(true, 2, 50, 9, 30));
  EXPECT_EQ(p.errors, counts(0, 0, 0, 1));
}

TEST(ExtStrips, DepthPastTheEndRoutesOnlyPixelsWhoseDepthExists) {
  Row row(20, 4);
  row.ext(0, ext(false, 1, 0, 0, 10), kDepth);  // colour 4..13, depth 14..23 of which 14..19
  const Parsed p = parse(row);
  ASSERT_EQ(p.strips.size(), 1u);
  EXPECT_EQ(p.strips[0].length, 6);
  EXPECT_EQ(p.strips[0].depth_x(), 14);
  EXPECT_EQ(p.errors, counts(0, 0, 0, 1));
}

TEST(ExtStrips, DepthWithNoDepthPixelLeftRoutesNothing) {
  for (int width : {20, 30}) {  // colour 4..23: all present, or partly; depth: none
    Row row(24, 3);
    row.ext(0, ext(false, 1, 0, 0, width), kDepth);
    const Parsed p = parse(row);
    ASSERT_EQ(p.strips.size(), 1u) << width;
    EXPECT_EQ(p.strips[0].length, 0) << width;
    EXPECT_EQ(p.errors, counts(0, 0, 0, 1)) << width;
  }
}

TEST(ExtStrips, WordInTheLastTwoPixelsIsATruncationOfLengthZero) {
  Row row(8, 3);
  row.header(0, StripHeader::skip(false, 2));  // strip 2..3
  row.ext(4, ext(false, 0, 0, 0, 3), kKeyGreen);
  const Parsed p = parse(row);
  ASSERT_EQ(p.strips.size(), 2u);
  EXPECT_EQ(p.strips[1].source_x, 8);
  EXPECT_EQ(p.strips[1].length, 0);
  EXPECT_EQ(p.errors, counts(0, 0, 0, 1));
}

TEST(ExtStrips, DepthEndingExactlyAtTheRowEndIsNotTruncated) {
  Row row(24, 3);
  row.ext(0, ext(false, 1, 0, 0, 10), kDepth);  // 4 + 2·10 = 24
  const Parsed p = parse(row);
  ASSERT_EQ(p.strips.size(), 1u);
  EXPECT_EQ(p.strips[0].length, 10);
  EXPECT_EQ(p.errors, StripErrorCounts{});
}

TEST(ExtStrips, ACallbackReturningFalseDropsTheRestUncounted) {
  Row row(40, 3);
  row.ext(0, ext(false, 0, 0, 0, 4), kKeyGreen);
  row.header(8, StripHeader::copy(false, 0, 0, 0, 100));  // truncated, were it parsed
  StripErrorCounts errors;
  int seen = 0;
  const int strips =
      parse_scanline(row.bytes.data(), row.width(), 3, errors, [&](const ParsedStrip& s) {
        ++seen;
        return !s.is(ExtKind::Key);
      });
  EXPECT_EQ(seen, 1);
  EXPECT_EQ(strips, 1);
  EXPECT_EQ(errors, StripErrorCounts{});
}

TEST(ExtStrips, RandomBytesNeverLeaveTheRow) {
  // Run under ASan: colour and depth spans handed over lie inside the row, whatever the bytes.
  std::mt19937_64 rng(4321);
  const std::uint64_t words[] = {kKeyGreen, kDepth, kKind3, 0};
  for (int i = 0; i < 20000; ++i) {
    const int bpp = (i % 2) ? 3 : 4;
    const int width = static_cast<int>(rng() % 200);
    auto row = std::make_unique<std::uint8_t[]>(static_cast<std::size_t>(width) * bpp);
    for (int b = 0; b < width * bpp; ++b) row[b] = static_cast<std::uint8_t>(rng());
    for (int x = 0; x + 3 < width; x += 5) {
      if (rng() % 3 == 0) {
        const int w = static_cast<int>(rng() % 8);
        write_header_pixels(encode(ext(false, 0, 0, 0, w)), &row[x * bpp], bpp);
        write_header_pixels(words[rng() % 4], &row[(x + 2) * bpp], bpp);
      }
    }
    StripErrorCounts errors;
    long pixels = 0;
    parse_scanline(row.get(), width, bpp, errors, [&](const ParsedStrip& s) {
      ASSERT_GE(s.header_x(), 0);
      ASSERT_GE(s.length, 0);
      ASSERT_LE(s.source_x + s.length, width);
      if (s.is(ExtKind::Depth) && s.length > 0) {  // depth_x() is past the row when none is left
        ASSERT_LE(s.depth_x() + s.length, width);
      }
      pixels += s.length * (s.is(ExtKind::Depth) ? 2 : 1);
    });
    ASSERT_LE(pixels, width);
  }
}

}  // namespace
}  // namespace l2
