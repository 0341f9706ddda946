// A picture through a per-pixel choice of colour tables: each pixel through its own table (the
// expected bytes written out here), compose() as one lookup of two tables, and a picture of the
// wrong size refused.
#include <gtest/gtest.h>

#include <stdexcept>

#include "image/table_map.hpp"

namespace l2 {
namespace {

// Every byte halved, rounded down, in every channel.
ColourTable halving() {
  ColourTable t;
  for (auto& c : t.channel)
    for (int i = 0; i < 256; ++i) c[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i / 2);
  return t;
}

TEST(TableMap, EachPixelThroughItsOwnTable) {
  ColourTable plus_one = ColourTable::identity();
  for (auto& c : plus_one.channel) c[7] = 8;
  const TableMap map{3, 2, {0, 1, 2, 2, 1, 0}, {ColourTable::identity(), halving(), plus_one}};
  RgbImage in(3, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) in.set(x, y, {7, 100, 255});
  RgbImage out;
  apply_table_map(map, in, out);
  ASSERT_EQ(out.width(), 3);
  ASSERT_EQ(out.height(), 2);
  EXPECT_EQ(out.at(0, 0), (Rgb{7, 100, 255}));  // identity
  EXPECT_EQ(out.at(1, 0), (Rgb{3, 50, 127}));   // halved, down
  EXPECT_EQ(out.at(2, 0), (Rgb{8, 100, 255}));  // 7 -> 8 only
  EXPECT_EQ(out.at(0, 1), (Rgb{8, 100, 255}));
  EXPECT_EQ(out.at(1, 1), (Rgb{3, 50, 127}));
  EXPECT_EQ(out.at(2, 1), (Rgb{7, 100, 255}));
  // In place too.
  apply_table_map(map, in, in);
  EXPECT_EQ(in.at(1, 1), (Rgb{3, 50, 127}));
}

TEST(TableMap, RefusesAPictureOfAnotherSize) {
  const TableMap map{2, 2, {0, 0, 0, 0}, {ColourTable::identity()}};
  RgbImage out;
  EXPECT_THROW(apply_table_map(map, RgbImage(3, 2), out), std::invalid_argument);
}

TEST(ColourTable, ComposeLooksUpTheFirstThenTheSecond) {
  ColourTable plus_one = ColourTable::identity();
  for (auto& c : plus_one.channel) c[50] = 51;
  const ColourTable t = compose(halving(), plus_one);
  EXPECT_EQ(t.channel[0][100], 51);  // 100 / 2 = 50, then 51
  EXPECT_EQ(t.channel[1][101], 51);  // 50 (down), then 51
  EXPECT_EQ(t.channel[2][255], 127);
  EXPECT_EQ(compose(plus_one, halving()).channel[0][50], 25);  // 51 / 2, down
}

}  // namespace
}  // namespace l2
