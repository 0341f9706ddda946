// Alpha and beta maps in the wall file (`alpha`, `beta`, `alpha_gamma` of a [[display]]): the
// gains and offsets a display gets from grey PNGs written here, and every refusal's exact line.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "grey_png.hpp"
#include "image/png_io.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_folder.hpp"

namespace l2 {
namespace {

using testing_support::write_grey_png;

class WallLevels : public WallFolder {
 protected:
  WallLevels() : WallFolder("levels") {}
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
};

TEST_F(WallLevels, AlphaAndBetaBecomeGainsAndOffsets) {
  write_grey_png(dir_ / "calibration/a.png", 4, 2, {255, 255, 128, 0, 255, 255, 255, 255});
  write_grey_png(dir_ / "calibration/b.png", 4, 2, {0, 51, 0, 0, 0, 0, 0, 0});
  const Wall wall =
      parse(one_display_wall("alpha = \"calibration/a.png\"\nbeta = \"calibration/b.png\""));
  const Display& d = wall.displays[0];
  EXPECT_EQ(d.alpha, "calibration/a.png");
  EXPECT_EQ(d.beta, "calibration/b.png");
  EXPECT_EQ(d.alpha_gamma, 1.0);
  ASSERT_TRUE(d.level_map);
  // Pixel 0 as it is; pixel 1 beta 0.2: gain 0.8 (52428.8 -> 52429), offset 51 * 65536;
  // pixel 2 alpha 128/255 (32896.502 -> 32897); pixel 3 alpha 0.
  EXPECT_EQ(d.level_map->gain,
            (std::vector<std::uint32_t>{65536, 52429, 32897, 0, 65536, 65536, 65536, 65536}));
  EXPECT_EQ(d.level_map->offset[1], 51u * 65536);
  EXPECT_EQ(d.level_map->offset[0], 0u);
}

TEST_F(WallLevels, AnAlphaGammaTakesTheMapAsLinearLight) {
  write_grey_png(dir_ / "a.png", 4, 2, {64, 255, 255, 255, 255, 255, 255, 255});
  const Wall wall = parse(one_display_wall("alpha = \"a.png\"\nalpha_gamma = 2.2"));
  ASSERT_TRUE(wall.displays[0].level_map);
  EXPECT_EQ(wall.displays[0].alpha_gamma, 2.2);
  EXPECT_EQ(wall.displays[0].level_map->gain[0], 34961u);  // (64/255)^(1/2.2) * 65536, rounded
}

TEST_F(WallLevels, MapsThatChangeNothingCostNothing) {
  write_grey_png(dir_ / "a.png", 4, 2, std::vector<std::uint8_t>(8, 255));
  write_grey_png(dir_ / "b.png", 4, 2, std::vector<std::uint8_t>(8, 0));
  const Wall wall = parse(one_display_wall("alpha = \"a.png\"\nbeta = \"b.png\""));
  EXPECT_FALSE(wall.displays[0].level_map);
}

TEST_F(WallLevels, ErrorsNameTheLineTheFieldAndTheFile) {
  const std::string f = wall_file();
  write_grey_png(dir_ / "wide.png", 5, 2, std::vector<std::uint8_t>(10, 9));
  write_png(dir_ / "colour.png", RgbImage(4, 2, Rgb{1, 2, 3}));
  write_grey_png(dir_ / "a.png", 4, 2, std::vector<std::uint8_t>(8, 9));
  EXPECT_EQ(error_of(one_display_wall("alpha = \"wide.png\"")),
            f + ":6: display[0].alpha: " + file("wide.png") + ": 5x2, but the display is 4x2");
  EXPECT_EQ(
      error_of(one_display_wall("beta = \"colour.png\"")),
      f + ":6: display[0].beta: " + file("colour.png") + ": must be a grey PNG, got colour png");
  EXPECT_EQ(error_of(one_display_wall("alpha = \"\"")),
            f + ":6: display[0].alpha: must name a grey PNG file, got \"\"");
  EXPECT_EQ(error_of(one_display_wall("alpha = \"/dev/null\"")),
            f + ":6: display[0].alpha: /dev/null: not a regular file: a map is a PNG file");
  EXPECT_EQ(error_of(one_display_wall("alpha_gamma = 2.2")),
            f + ":6: display[0].alpha_gamma: needs an alpha map (alpha = \"...\")");
  EXPECT_EQ(error_of(one_display_wall("alpha = \"a.png\"\nalpha_gamma = 0.5")),
            f + ":7: display[0].alpha_gamma: must be a number 1..4, got 0.5");
  EXPECT_EQ(error_of(one_display_wall("alpha = \"a.png\"\nalpha_gamma = \"x\"")),
            f + ":7: display[0].alpha_gamma: must be a number 1..4, got a string");
  // A file that is not a PNG: read_png's own one line, after the wall's line and field.
  write("text.png", "not a picture");
  EXPECT_EQ(error_of(one_display_wall("beta = \"text.png\""))
                .rfind(f + ":6: display[0].beta: " + file("text.png"), 0),
            0u);
}

}  // namespace
}  // namespace l2
