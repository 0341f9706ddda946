// The colour stage both display paths hand their pictures through: each display's own table,
// the expected bytes worked out here from the gain/offset rule; a display without one, or one
// lost (an empty picture), handed out as it is.
#include "l2wall/colour_stage.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace l2 {
namespace {

TEST(ColourStage, AppliesEachDisplaysOwnTable) {
  Wall wall;
  wall.displays.resize(3);
  for (int i = 0; i < 3; ++i) wall.displays[static_cast<std::size_t>(i)].id = i;
  ColourMatch& half = wall.displays[0].colour;
  half.kind = ColourMatch::Kind::Gain;
  half.gain = {0.5, 1.0, 1.0};
  half.offset = {0, 10, 0};
  half.table = colour_table_from_gain(half.gain, half.offset);
  // Written as a correction, working out to none: nothing to apply.
  wall.displays[2].colour.kind = ColourMatch::Kind::Gain;

  std::vector<RgbImage> raw(3, RgbImage(2, 1));
  raw[0].set(0, 0, {9, 250, 7});
  raw[0].set(1, 0, {200, 0, 255});
  raw[1].set(0, 0, {9, 250, 7});
  raw[2].set(0, 0, {1, 2, 3});
  const ColourStage stage(wall);
  EXPECT_TRUE(stage.applies());
  const DisplayPictures shown =
      stage.apply([&](int d) -> const RgbImage& { return raw[static_cast<std::size_t>(d)]; });
  const RgbImage& zero = shown(0);
  EXPECT_EQ(zero.at(0, 0), (Rgb{5, 255, 7}));     // 4.5 -> 5, 260 -> 255, 7
  EXPECT_EQ(zero.at(1, 0), (Rgb{100, 10, 255}));  // 100, 0 + 10, 255
  EXPECT_EQ(raw[0].at(0, 0), (Rgb{9, 250, 7}));   // the path's own picture is left as it was
  EXPECT_EQ(&shown(1), &raw[1]);
  EXPECT_EQ(&shown(2), &raw[2]);
  raw[0] = RgbImage();
  EXPECT_TRUE(shown(0).empty());

  const ColourStage none(Wall{});
  EXPECT_FALSE(none.applies());
}

// A frame's pictures asked for again (saved, then compared, then published) are made once: the
// path's picture is read only the first time for that frame, and again for a new frame or where
// the caller did not say which frame it is.
TEST(ColourStage, MakesEachDisplaysPictureOfAFrameOnce) {
  Wall wall;
  wall.displays.resize(1);
  ColourMatch& c = wall.displays[0].colour;
  c.kind = ColourMatch::Kind::Gain;
  c.offset = {1, 0, 0};
  c.table = colour_table_from_gain(c.gain, c.offset);
  RgbImage raw(1, 1, Rgb{10, 20, 30});
  int reads = 0;
  const DisplayPictures path = [&](int) -> const RgbImage& {
    ++reads;
    return raw;
  };
  const ColourStage stage(wall);
  EXPECT_EQ(stage.apply(path, 7)(0).at(0, 0), (Rgb{11, 20, 30}));
  raw.set(0, 0, {50, 20, 30});
  EXPECT_EQ(stage.apply(path, 7)(0).at(0, 0), (Rgb{11, 20, 30}));  // frame 7 as made
  EXPECT_EQ(reads, 1);
  EXPECT_EQ(stage.apply(path, 8)(0).at(0, 0), (Rgb{51, 20, 30}));
  EXPECT_EQ(stage.apply(path)(0).at(0, 0), (Rgb{51, 20, 30}));
  EXPECT_EQ(stage.apply(path, 8)(0).at(0, 0), (Rgb{51, 20, 30}));  // made again: unkeyed between
  EXPECT_EQ(reads, 4);
}

// Two 4x1 projectors overlapping by 2 columns (display 1 at canvas column 2), blended linearly:
// over the overlap display 0 weighs 1.5/2 and 0.5/2 of each byte, display 1 the rest (rounded,
// halves up); display 1 also adds 1 to green, after its blend.
TEST(ColourStage, BlendsOverlappingProjectorsThenMatchesColour) {
  Wall wall;
  wall.blend.on = true;
  wall.displays.resize(2);
  for (int i = 0; i < 2; ++i) {
    Display& d = wall.displays[static_cast<std::size_t>(i)];
    d.id = i;
    d.width = 4;
    d.height = 1;
    d.canvas_x = 2 * i;
  }
  ColourMatch& green = wall.displays[1].colour;
  green.kind = ColourMatch::Kind::Gain;
  green.offset = {0, 1, 0};
  green.table = colour_table_from_gain(green.gain, green.offset);

  std::vector<RgbImage> raw(2, RgbImage(4, 1, Rgb{200, 200, 10}));
  const ColourStage stage(wall);
  EXPECT_TRUE(stage.applies());
  const DisplayPictures shown =
      stage.apply([&](int d) -> const RgbImage& { return raw[static_cast<std::size_t>(d)]; });
  const RgbImage& zero = shown(0);
  EXPECT_EQ(zero.at(0, 0), (Rgb{200, 200, 10}));
  EXPECT_EQ(zero.at(1, 0), (Rgb{200, 200, 10}));
  EXPECT_EQ(zero.at(2, 0), (Rgb{150, 150, 8}));  // 0.75: 150, 7.5 -> 8
  EXPECT_EQ(zero.at(3, 0), (Rgb{50, 50, 3}));    // 0.25: 50, 2.5 -> 3
  const RgbImage& one = shown(1);
  EXPECT_EQ(one.at(0, 0), (Rgb{50, 51, 3}));
  EXPECT_EQ(one.at(1, 0), (Rgb{150, 151, 8}));
  EXPECT_EQ(one.at(2, 0), (Rgb{200, 201, 10}));
  EXPECT_EQ(one.at(3, 0), (Rgb{200, 201, 10}));
}

}  // namespace
}  // namespace l2
