// The acceptance check on every example wall in walls/ and every scene: the frames of
// all pipeservers decode with zero spec §3 errors, and routing their strips rebuilds each
// display equal to its reference render, bit for bit.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "test_support.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_scenes.hpp"

namespace l2 {
namespace {

TEST(ExampleWalls, ThereAreSome) {
  EXPECT_GE(test::example_walls().size(), 3u);
}

// One test per wall and scene, so ctest can spread them over cores.
class ExampleWall : public ::testing::TestWithParam<test::WallScene> {};

TEST_P(ExampleWall, ReassemblesToTheReference) {
  {
    const auto& [path, name] = GetParam();
    const TileLayout layout = plan_layout(load_wall(path));
    {
      auto scene = make_scene(name, test::small_options());
      const int frame = 3;
      const auto check = test::check_wall(layout, *scene, frame);
      SCOPED_TRACE(path.filename().string() + " " + name);
      EXPECT_EQ(check.reassembly.errors.total(), 0u);
      EXPECT_EQ(check.reassembly.parities_seen, std::vector<int>{frame % 2});
      // Bit for bit (README.md, "Reassembly is exact"), sort-first, sort-last and hybrid.
      test::ImageDiff all;
      for (const auto& d : check.diffs) all += d;
      EXPECT_EQ(all.pixels_differing, 0) << "max channel diff " << all.max_channel_diff;
      // Every tile pixel arrives, exactly once: on a sort-first wall every display pixel (tiles
      // cover every display), and the overlay's. A depth layer sends only the pixels that can
      // change the display (sparse DEPTH rows, tilelayout/sparse_depth.hpp): at most once a
      // layer, which the bit-for-bit check above holds to the reference.
      long tile_pixels = 0;
      for (const DisplayTile& t : layout.tiles) tile_pixels += t.on_display.area();
      const long arrived = check.reassembly.copied_pixels + check.reassembly.composited_pixels;
      if (layout.wall.depth_layers == 0) {
        EXPECT_EQ(arrived, tile_pixels);
      } else {
        EXPECT_LE(arrived, tile_pixels);
      }
      if (layout.wall.depth_layers == 0 && !layout.wall.overlay) {
        EXPECT_EQ(check.reassembly.copied_pixels, check.display_pixels);
      }
    }
  }
}

// Under AddressSanitizer a diagonal: every wall and every scene is still checked there, each at
// least once, in one test a wall (or a scene, when there are more scenes) instead of one for
// every pairing: the 72 pairings, some seconds each under the sanitizer, took most of the ASan
// run's time in CI. The release build, where the whole sweep is quick, keeps every pairing.
INSTANTIATE_TEST_SUITE_P(Walls, ExampleWall,
                         ::testing::ValuesIn(test::kAddressSanitizer ? test::diagonal_wall_scenes()
                                                                     : test::all_wall_scenes()),
                         test::wall_scene_name);

}  // namespace
}  // namespace l2
