#include "tilelayout/test_pattern.hpp"

#include <gtest/gtest.h>

#include <set>

namespace l2 {
namespace {

TEST(TestPattern, MatchesTheDocumentedFormula) {
  // mask(0) = 0x5BD1E9; (0,0) encodes to the mask itself.
  EXPECT_EQ(test_pattern(0, 0, 0), (Rgb{0x5B, 0xD1, 0xE9}));
  // v = 1<<12 | 2 = 0x001002, mask(1) = 2*0x5BD1E9 = 0xB7A3D2, colour = 0xB7B3D0.
  EXPECT_EQ(test_pattern(1, 1, 2), (Rgb{0xB7, 0xB3, 0xD0}));
  // x = 4095, y = 4095: v = 0xFFFFFF; mask(63) = 64*0x5BD1E9 mod 2^24 = 0xF47A40.
  EXPECT_EQ(test_pattern(63, 4095, 4095), (Rgb{0x0B, 0x85, 0xBF}));
}

TEST(TestPattern, RoundTripsEveryDisplayOverTheWholeCoordinateRange) {
  for (int d = 0; d < 64; ++d) {
    for (int x = 0; x < 4096; x += 37) {
      for (int y = 0; y < 4096; y += 41) {
        const auto pos = test_pattern_position(d, test_pattern(d, x, y));
        ASSERT_TRUE(pos.has_value());
        ASSERT_EQ(*pos, std::make_pair(x, y)) << d;
      }
    }
    const auto corner = test_pattern_position(d, test_pattern(d, 4095, 4095));
    EXPECT_EQ(*corner, std::make_pair(4095, 4095));
  }
}

TEST(TestPattern, MasksAreDistinctAndNonZero) {
  std::set<unsigned> masks;
  for (int d = 0; d < 64; ++d) {
    EXPECT_NE(test_pattern_mask(d), 0u);
    EXPECT_LE(test_pattern_mask(d), 0xFFFFFFu);
    masks.insert(test_pattern_mask(d));
  }
  EXPECT_EQ(masks.size(), 64u);
}

TEST(TestPattern, WrongDisplayOrRowDecodesElsewhere) {
  const Rgb c = test_pattern(3, 100, 200);
  for (int d = 0; d < 64; ++d) {
    if (d == 3) continue;
    EXPECT_NE(*test_pattern_position(d, c), std::make_pair(100, 200)) << d;
  }
  EXPECT_NE(test_pattern(3, 100, 201), c);
  EXPECT_NE(test_pattern(3, 101, 200), c);
}

TEST(TestPattern, RejectsDisplaysOutsideTheHeaderRange) {
  EXPECT_FALSE(test_pattern_position(64, {}).has_value());
  EXPECT_FALSE(test_pattern_position(-1, {}).has_value());
}

}  // namespace
}  // namespace l2
