// tilelayout on walls of several meshes, as a user runs it: the plan of each mesh under its
// line, --verify checking each mesh with its report lines named, --png's picture of the meshes.
#include <gtest/gtest.h>

#include "cli_run.hpp"
#include "image/png_io.hpp"
#include "tilelayout/pictures.hpp"
#include "tilelayout/test_pattern.hpp"

namespace l2 {
namespace {

using cli_testing::ChildRun;
using cli_testing::Cli;
namespace fs = std::filesystem;

// 10 x 7 displays of 40x30 (70: two meshes, the left 5 columns and the right 5), one
// pipeserver a display.
const std::string kSeventy =
    "[display_grid]\ncolumns = 10\nrows = 7\nwidth = 40\nheight = 30\n"
    "[tiling]\nkind = \"grid\"\ntile_width = 40\ntile_height = 30\n"
    "[pipeservers]\ncount = 70\nframebuffer_width = 45\nframebuffer_height = 30\n";

TEST_F(Cli, SeveralMeshesArePlannedEachUnderItsLine) {
  const ChildRun r =
      run("--wall '" + (fs::path(L2_WALLS_DIR) / "stallion-16x5.toml").string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("80 displays in 2 meshes (a strip header addresses 64 displays), 160 "
                       "pipeservers"),
            std::string::npos)
      << r.out.substr(0, 400);
  EXPECT_NE(r.out.find("\nmesh 1: 40 displays (wall displays 8-15, 24-31, 40-47, 56-63, 72-79 as "
                       "its displays 0-39), 80 pipeservers (80-159 as its inputs 0-79), 20 x 5 "
                       "boards\n"),
            std::string::npos);
}

TEST_F(Cli, VerifyChecksEveryMeshAndNamesItOnEveryLine) {
  const fs::path wall = write("seventy.toml", kSeventy);
  const ChildRun r = run("--wall '" + wall.string() + "' --verify '" + (dir_ / "v").string() +
                         "' --png '" + (dir_ / "png").string() + "'");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("verifying mesh 1 (2 of 2): 35 displays, 35 pipeservers\n"),
            std::string::npos);
  EXPECT_NE(r.out.find("mesh 0: routing right: every planned pixel in place on 35 displays\n"),
            std::string::npos);
  EXPECT_NE(r.out.find("mesh 1: display 34 (40x30) right: 1200 planned pixels: 1200 right"),
            std::string::npos);
  EXPECT_NE(r.out.find("every mesh right: 70 displays in 2 meshes\n"), std::string::npos);
  // Mesh 1's display 0 is the wall's display 5 (row 0, column 5): its pixels are the routing
  // test pattern of display 0 of that mesh, as its headers address it.
  const RgbImage shown = read_png(dir_ / "v" / "mesh-1" / "display-0.png");
  ASSERT_EQ(shown.width(), 40);
  for (int y = 0; y < 30; y += 7) {
    for (int x = 0; x < 40; x += 3)
      ASSERT_EQ(shown.at(x, y), test_pattern(0, x, y)) << x << "," << y;
  }
  EXPECT_TRUE(fs::exists(dir_ / "v" / "mesh-0" / "scanout-34.png"));
  EXPECT_FALSE(fs::exists(dir_ / "v" / "mesh-0" / "display-35.png"));
  // The picture of the meshes: a display of each in its mesh's colour, inside its outline.
  const RgbImage meshes = read_png(dir_ / "png" / "meshes.png");
  EXPECT_EQ(meshes.at(3, 3), palette_colour(0));
  EXPECT_EQ(meshes.at(9 * 40 + 3, 6 * 30 + 3), palette_colour(1));
  EXPECT_TRUE(fs::exists(dir_ / "png" / "mesh-1" / "wall.png"));
}

TEST_F(Cli, AMeshThatDoesNotFitIsNamed) {
  std::string text = kSeventy;
  text.replace(text.find("framebuffer_width = 45"), 22, "framebuffer_width = 40");
  const ChildRun r = run("--wall '" + write("narrow.toml", text).string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind("tilelayout: mesh 0 (wall displays 0-4, 10-14, 20-24, 30-34, 40-44, "
                        "50-54, 60-64; pipeservers 0..34 as its inputs 0..34): ",
                        0),
            0u)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace l2
