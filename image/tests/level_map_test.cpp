// Alpha and beta maps as per-pixel gains and offsets (image/level_map.hpp): each expected byte
// worked out here from the rule as docs/wall-file.md states it.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "image/level_map.hpp"

namespace l2 {
namespace {

// The documented rule in integers: gain and offset in 1/65536, then (in * gain + offset +
// 32768) / 65536 rounded down.
int by_rule(int in, int alpha, double gamma, int beta) {
  const double a = alpha / 255.0, b = beta / 255.0;
  const auto gain =
      static_cast<long long>(std::floor(std::pow(a, 1 / gamma) * (1 - b) * 65536 + 0.5));
  const auto offset = static_cast<long long>(std::floor(b * 255 * 65536 + 0.5));
  return static_cast<int>((in * gain + offset + 32768) >> 16);
}

TEST(LevelMap, AlphaMultipliesCodeValuesRoundingHalvesUp) {
  const LevelMap m = level_map(3, 1, std::vector<std::uint8_t>{255, 128, 0}, 1.0, {});
  EXPECT_EQ(m.gain[0], 65536u);
  EXPECT_EQ(m.gain[1], 32897u);  // 128/255 * 65536 = 32896.502, rounded
  EXPECT_EQ(m.offset[1], 0u);
  RgbImage in(3, 1, Rgb{200, 255, 1});
  RgbImage out;
  apply_level_map(m, in, out);
  EXPECT_EQ(out.at(0, 0), (Rgb{200, 255, 1}));
  // (200 * 32897 + 32768) / 65536 = 100.89 -> 100; 255 -> 128.5 -> 128; 1 -> 1
  EXPECT_EQ(out.at(1, 0), (Rgb{100, 128, 1}));
  EXPECT_EQ(out.at(2, 0), (Rgb{0, 0, 0}));
}

TEST(LevelMap, AlphaAtAGammaIsLinearLight) {
  // Alpha 64 at gamma 2.2: (64/255)^(1/2.2) = 0.5333 of each code value.
  const LevelMap m = level_map(1, 1, std::vector<std::uint8_t>{64}, 2.2, {});
  RgbImage in(1, 1, Rgb{255, 128, 10});
  apply_level_map(m, in, in);  // in place
  EXPECT_EQ(in.at(0, 0).r, by_rule(255, 64, 2.2, 0));
  EXPECT_EQ(in.at(0, 0).r, 136);
  EXPECT_EQ(in.at(0, 0).g, 68);
  EXPECT_EQ(in.at(0, 0).b, 5);
}

TEST(LevelMap, BetaRaisesTheBlackLevelAndKeepsWhite) {
  const LevelMap m = level_map(2, 1, {}, 1.0, std::vector<std::uint8_t>{0, 51});
  RgbImage in(2, 1, Rgb{0, 255, 100});
  RgbImage out;
  apply_level_map(m, in, out);
  EXPECT_EQ(out.at(0, 0), (Rgb{0, 255, 100}));
  // b = 0.2: 0 -> 51, 255 -> 51 + 204 = 255, 100 -> 51 + 80 = 131.
  EXPECT_EQ(out.at(1, 0), (Rgb{51, 255, 131}));
}

TEST(LevelMap, AlphaThenBetaOverEveryByte) {
  const int alpha = 200, beta = 30;
  const LevelMap m =
      level_map(1, 1, std::vector<std::uint8_t>{alpha}, 2.2, std::vector<std::uint8_t>{beta});
  for (int v = 0; v < 256; ++v) {
    const auto b = static_cast<std::uint8_t>(v);
    RgbImage in(1, 1, Rgb{b, b, b});
    apply_level_map(m, in, in);
    EXPECT_EQ(in.at(0, 0).r, by_rule(v, alpha, 2.2, beta)) << v;
    // Within one of the rule in real numbers.
    const double exact = beta + v * std::pow(alpha / 255.0, 1 / 2.2) * (1 - beta / 255.0);
    EXPECT_LE(std::abs(in.at(0, 0).r - exact), 0.51) << v;
  }
}

TEST(LevelMap, NoMapsChangeNothingAndWrongSizesAreRefused) {
  EXPECT_TRUE(is_identity(level_map(2, 2, {}, 1.0, {})));
  EXPECT_TRUE(is_identity(
      level_map(1, 1, std::vector<std::uint8_t>{255}, 2.2, std::vector<std::uint8_t>{0})));
  EXPECT_THROW(level_map(2, 2, std::vector<std::uint8_t>(3), 1.0, {}), std::invalid_argument);
  EXPECT_THROW(level_map(2, 2, {}, 1.0, std::vector<std::uint8_t>(5)), std::invalid_argument);
  EXPECT_THROW(level_map(1, 1, {}, 0.0, {}), std::invalid_argument);
  RgbImage out;
  EXPECT_THROW(apply_level_map(level_map(2, 1, {}, 1.0, {}), RgbImage(1, 1), out),
               std::invalid_argument);
}

}  // namespace
}  // namespace l2
