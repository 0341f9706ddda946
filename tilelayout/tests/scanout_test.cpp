// Every example wall, planned and scanned out with the test pattern, must route every visible
// display pixel exactly once with nothing but valid headers.
#include <gtest/gtest.h>

#include <filesystem>

#include "routing_check.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/test_frame.hpp"
#include "tilelayout/test_pattern.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

std::vector<std::filesystem::path> example_walls() {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(L2_WALLS_DIR)) {
    if (e.path().extension() != ".toml") continue;
    // Walls of several meshes have tests of their own (several_meshes_test.cpp).
    if (load_wall(e.path()).mesh_count == 1) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Scanout, ThereAreExampleWalls) {
  EXPECT_GE(example_walls().size(), 4u);
}

TEST(Scanout, EveryExampleWallRoutesEveryDisplayPixelExactlyOnce) {
  for (const auto& path : example_walls()) {
    SCOPED_TRACE(path.string());
    const TileLayout layout = plan_layout(load_wall(path));
    EXPECT_TRUE(layout.warnings.empty());
    // This check copies COPY strips only; walls that composite (KEY, DEPTH) are checked by the
    // verifier, which composites (verify/tests: every example wall verifies clean).
    if (layout.wall.depth_layers != 0 || layout.wall.overlay) continue;
    for (bool parity : {false}) {  // parity 1: the child-process test in cli_test.cpp
      std::vector<RgbImage> frames;
      for (const PipeserverPlan& s : layout.pipeservers) frames.push_back(test_frame(s, parity));
      const RoutingCheck c = check_routing(layout.wall, frames, parity);
      long long visible = 0;
      for (const Display& d : layout.wall.displays) visible += 1LL * d.width * d.height;
      EXPECT_EQ(c.errors.total(), 0u);
      EXPECT_EQ(c.copied, visible);
      EXPECT_EQ(c.outside, 0);
      EXPECT_EQ(c.wrong_colour, 0);
      EXPECT_EQ(c.wrong_parity, 0);
      EXPECT_EQ(c.uncovered, 0);
      EXPECT_EQ(c.covered_twice, 0);
    }
  }
}

TEST(Scanout, TheCheckCatchesAMisroutedStrip) {
  // Guards the guard: a frame with one header pointing a row lower must fail the check.
  const TileLayout layout = plan_layout(default_wall());
  std::vector<RgbImage> frames;
  for (const PipeserverPlan& s : layout.pipeservers) frames.push_back(test_frame(s, false));
  const PackedTile& p = layout.pipeservers[0].tiles[0];
  const Rect& d = p.tile.on_display;
  write_header_pixels(encode(StripHeader::copy(false, p.tile.display, d.x, d.y + 1, d.w)),
                      frames[0].row(p.fb_y).data() + (p.fb_x - 2) * 3, 3);
  const RoutingCheck c = check_routing(layout.wall, frames, false);
  EXPECT_EQ(c.wrong_colour, d.w);
  EXPECT_EQ(c.covered_twice, d.w);
  EXPECT_EQ(c.uncovered, d.w);
}

// The canvas pattern carries each pixel's canvas position: a tile's first pixel decodes to the
// tile's canvas corner, which differs from its display corner on every display but one at the
// canvas origin.
TEST(Scanout, TheCanvasPatternEncodesCanvasPositions) {
  const TileLayout layout = plan_layout(default_wall());
  for (const PipeserverPlan& s : layout.pipeservers) {
    const RgbImage frame = test_frame(s, false, PatternPlace::Canvas);
    for (const PackedTile& p : s.tiles) {
      const Rgb first = frame.at(p.fb_x, p.fb_y);
      EXPECT_EQ(first, test_pattern(p.tile.display, p.tile.on_canvas.x, p.tile.on_canvas.y));
    }
  }
}

}  // namespace
}  // namespace l2
