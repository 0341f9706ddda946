// Colour tables: entries of the gain/offset formula worked out by hand in the comments (real
// arithmetic, round half up, then clamp), and a picture looked up byte by byte.
#include <gtest/gtest.h>

#include "image/colour_table.hpp"

namespace l2 {
namespace {

TEST(ColourTable, IdentityMapsEveryByteToItself) {
  const ColourTable t = ColourTable::identity();
  EXPECT_TRUE(t.is_identity());
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(t.channel[c][0], 0);
    EXPECT_EQ(t.channel[c][137], 137);
    EXPECT_EQ(t.channel[c][255], 255);
  }
  EXPECT_TRUE(colour_table_from_gain({1, 1, 1}, {0, 0, 0}).is_identity());
}

TEST(ColourTable, GainAndOffsetAsWorkedByHand) {
  const ColourTable t = colour_table_from_gain({1.0, 0.96, 0.92}, {0, 0, 4});
  EXPECT_FALSE(t.is_identity());
  EXPECT_EQ(t.channel[0][200], 200);  // 200 * 1
  EXPECT_EQ(t.channel[1][0], 0);
  EXPECT_EQ(t.channel[1][13], 12);    // 12.48
  EXPECT_EQ(t.channel[1][100], 96);   // 96.0
  EXPECT_EQ(t.channel[1][255], 245);  // 244.8
  EXPECT_EQ(t.channel[2][0], 4);      // 0 + 4
  EXPECT_EQ(t.channel[2][250], 234);  // 230.0 + 4
  EXPECT_EQ(t.channel[2][255], 239);  // 234.6 -> 235, + 4
}

TEST(ColourTable, HalvesRoundUp) {
  const ColourTable t = colour_table_from_gain({0.5, 0.5, 0.5}, {0, 0, 0});
  EXPECT_EQ(t.channel[0][1], 1);      // 0.5
  EXPECT_EQ(t.channel[0][3], 2);      // 1.5
  EXPECT_EQ(t.channel[0][4], 2);      // 2.0
  EXPECT_EQ(t.channel[0][255], 128);  // 127.5
}

TEST(ColourTable, ClampsToTheByte) {
  const ColourTable t = colour_table_from_gain({2.0, 4.0, 1.0}, {0, 0, -10});
  EXPECT_EQ(t.channel[0][127], 254);  // 254
  EXPECT_EQ(t.channel[0][128], 255);  // 256
  EXPECT_EQ(t.channel[1][255], 255);  // 1020
  EXPECT_EQ(t.channel[2][5], 0);      // -5
  EXPECT_EQ(t.channel[2][10], 0);     // 0
  EXPECT_EQ(t.channel[2][11], 1);     // 1
}

TEST(ColourTable, AppliesEveryByteOfAPicture) {
  const ColourTable t = colour_table_from_gain({1.0, 0.5, 2.0}, {1, 0, -1});
  RgbImage in(2, 2);
  in.set(0, 0, {10, 20, 30});
  in.set(1, 0, {255, 0, 128});
  in.set(0, 1, {0, 255, 1});
  in.set(1, 1, {100, 3, 127});
  RgbImage out;
  apply_colour(t, in, out);
  ASSERT_EQ(out.width(), 2);
  ASSERT_EQ(out.height(), 2);
  EXPECT_EQ(out.at(0, 0), (Rgb{11, 10, 59}));   // 10+1, 20*0.5, 30*2-1
  EXPECT_EQ(out.at(1, 0), (Rgb{255, 0, 255}));  // 256 -> 255, 0, 256-1
  EXPECT_EQ(out.at(0, 1), (Rgb{1, 128, 1}));    // 0+1, 127.5 -> 128, 2-1
  EXPECT_EQ(out.at(1, 1), (Rgb{101, 2, 253}));  // 100+1, 1.5 -> 2, 254-1
  // In place: the same bytes.
  apply_colour(t, in, in);
  EXPECT_EQ(in, out);
}

}  // namespace
}  // namespace l2
