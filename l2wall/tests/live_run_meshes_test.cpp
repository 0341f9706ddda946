// A wall of several meshes run live through `l2wall run` (issue 51): 65 displays, more than one
// mesh's 64, served by two, each with its own display ids and pipeservers. What a person in
// front of the wall sees is checked pixel by pixel on both paths, the expected pixels worked out
// here from the wall's numbers, and the summary says the swap lock spanned the meshes.
#include <gtest/gtest.h>

#include "image/png_io.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

constexpr int kColumns = 13, kRows = 5, kWidth = 16, kHeight = 12;

// 13 x 5 displays of 16x12, one tile each, four pipeservers: the planner gives the left 7
// columns (35 displays) and pipeservers 0-1 to mesh 0, the right 6 and pipeservers 2-3 to mesh
// 1. Swap group 0 spans both meshes; the bottom row is group 1, across both too.
std::string wall_text() {
  std::string groups;
  for (int i = 0; i < kColumns * kRows; ++i) groups += i / kColumns == kRows - 1 ? "1, " : "0, ";
  return fmt::format(
      "name = \"65 displays\"\n[display_grid]\ncolumns = {}\nrows = {}\nwidth = {}\nheight = {}\n"
      "swap_groups = [{}]\n[tiling]\nkind = \"grid\"\ntile_width = {}\ntile_height = {}\n"
      "[pipeservers]\ncount = 4\nframebuffer_width = 80\nframebuffer_height = 120\n",
      kColumns, kRows, kWidth, kHeight, groups, kWidth, kHeight);
}

// Canvas pixel (u, v) of the picture shown: each a colour of its own.
Rgb canvas_pixel(int u, int v) {
  return {static_cast<std::uint8_t>(u), static_cast<std::uint8_t>(v * 4),
          static_cast<std::uint8_t>((u + 3 * v) % 256)};
}

TEST(LiveRunMeshes, SixtyFiveDisplaysOnTwoMeshesShowThePictureOnBothPaths) {
  const ScratchDir dir("meshes");
  const int canvas_w = kColumns * kWidth, canvas_h = kRows * kHeight;
  RgbImage picture(canvas_w, canvas_h);
  for (int v = 0; v < canvas_h; ++v)
    for (int u = 0; u < canvas_w; ++u) picture.set(u, v, canvas_pixel(u, v));
  write_png(dir / "picture.png", picture);
  std::ofstream(dir / "wall.toml") << wall_text();
  WallRun run("meshes", {"--wall", (dir / "wall.toml").string(), "--scene", "picture", "--content",
                         (dir / "picture.png").string(), "--fit", "stretch", "--frames", "3",
                         "--refresh", "0", "--path", "both", "--compare"});
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  // Every pixel of every display, both paths: a stretched picture of the canvas's size is the
  // canvas pixel for pixel, so display (row r, column c) shows it from (16c, 12r).
  long wrong = 0;
  for (int d = 0; d < kColumns * kRows; ++d) {
    const int u0 = d % kColumns * kWidth, v0 = d / kColumns * kHeight;
    for (const char* path : {"", "-vizserver"}) {
      const RgbImage shown =
          read_png(run.out() / "frame-2" / fmt::format("display-{}{}.png", d, path));
      ASSERT_EQ(shown.width(), kWidth) << d;
      for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) wrong += !(shown.at(x, y) == canvas_pixel(u0 + x, v0 + y));
    }
  }
  EXPECT_EQ(wrong, 0);
  const std::string out = run.output();
  EXPECT_NE(out.find("on 65 displays from 4 pipeservers"), std::string::npos) << out;
  EXPECT_NE(out.find("swap lock: every display of each of 2 group(s) showed the same frame in all"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("meshes: 2 emulated in this process"), std::string::npos) << out;
  EXPECT_NE(out.find("  mesh 1: wall displays 7-12, 20-25, 33-38, 46-51, 59-64; pipeservers 2-3\n"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("compare: 195 display pictures identical byte for byte"), std::string::npos)
      << out;
  expect_clean(run);
}

// Balancing re-tiles the wall as a whole; a wall of several meshes is planned mesh by mesh.
TEST(LiveRunMeshes, BalancingIsRefusedInOneLine) {
  const ScratchDir dir("meshes-balance");
  std::ofstream(dir / "wall.toml") << wall_text();
  WallRun run("meshes-balance",
              {"--wall", (dir / "wall.toml").string(), "--balance", "strips", "--frames", "3"});
  const ExitStatus status = run.wait(60s);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(run.output().find("l2wall: --balance: balancing is for a wall of one mesh; this "
                              "wall's 65 displays need 2 meshes\n"),
            std::string::npos)
      << run.output();
  expect_clean(run);
}

}  // namespace
}  // namespace l2
