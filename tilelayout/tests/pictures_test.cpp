#include "tilelayout/pictures.hpp"

#include <gtest/gtest.h>

#include <set>

#include "tilelayout/planner.hpp"
#include "tilelayout/test_frame.hpp"
#include "tilelayout/test_pattern.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

constexpr Rgb kUnused{40, 40, 40};

DisplayTile tile(int display, int w, int h) {
  DisplayTile t;
  t.display = display;
  t.on_display = {0, 0, w, h};
  return t;
}

TEST(Pictures, PaletteColoursAreDistinct) {
  std::set<std::tuple<int, int, int>> seen;
  for (int i = 0; i < 64; ++i) {
    const Rgb c = palette_colour(i);
    seen.insert({c.r, c.g, c.b});
    EXPECT_NE(c, kUnused);
  }
  EXPECT_EQ(seen.size(), 64u);
}

TEST(Pictures, FramebufferShowsGapsTilesByDisplayAndUnusedSpace) {
  // Tile 0 (display 3, 40x30) at x 2..41, tile 1 (display 5, 20x10) at 44..63, W = 100.
  const PipeserverPlan plan = pack_tiles(0, 100, 50, {tile(3, 40, 30), tile(5, 20, 10)});
  const RgbImage pic = framebuffer_picture(plan);
  ASSERT_EQ(pic.width(), 100);
  ASSERT_EQ(pic.height(), 50);
  EXPECT_EQ(pic.at(0, 5), (Rgb{255, 255, 255}));    // header gap of tile 0
  EXPECT_EQ(pic.at(43, 20), (Rgb{255, 255, 255}));  // gap of tile 1, below the tile too
  EXPECT_EQ(pic.at(4, 3), palette_colour(3));
  EXPECT_EQ(pic.at(46, 3), palette_colour(5));
  EXPECT_EQ(pic.at(50, 20), kUnused);  // below the shorter tile
  EXPECT_EQ(pic.at(80, 5), kUnused);   // after the END
  EXPECT_EQ(pic.at(10, 40), kUnused);  // below the last row
}

TEST(Pictures, HeaderGapsOfLargeFramebuffersAreDrawnWider) {
  // 1024 columns: a 2-column gap would vanish when the picture is viewed scaled down, so it is
  // drawn 1024 / 256 = 4 wide, over the tile's first 2 columns.
  const PipeserverPlan plan = pack_tiles(0, 1024, 100, {tile(3, 40, 30)});
  const RgbImage pic = framebuffer_picture(plan);
  for (int x = 0; x < 4; ++x) EXPECT_EQ(pic.at(x, 5), (Rgb{255, 255, 255})) << x;
  EXPECT_EQ(pic.at(4, 5), palette_colour(3));
}

TEST(Pictures, TilesAreLabelledWithDisplayAndLogicalTile) {
  // "D3 L0", capitals 7 pixels tall (scale 1: 30 / 4 / 7 rounds down to 1), centred in the
  // 40x30 tile at columns 2..41: the capitals' top row is (30 - 7) / 2 = 11, the text's middle
  // the tile's, column 21 or 22. The tile has a one-pixel black outline. Ink is black blended over
  // the tile's colour at its edges.
  const PipeserverPlan plan = pack_tiles(0, 100, 50, {tile(3, 40, 30)});
  const RgbImage pic = framebuffer_picture(plan);
  const Rgb paper = palette_colour(3);
  int left = 1000, right = -1, top = 1000, bottom = -1, dark = 0;
  for (int y = 1; y < 29; ++y) {  // inside the tile's one-pixel outline
    for (int x = 3; x < 41; ++x) {
      const Rgb c = pic.at(x, y);
      if (c.r >= paper.r || c.g >= paper.g || c.b >= paper.b) continue;  // no ink
      dark += c.r < paper.r / 2 && c.g < paper.g / 2 && c.b < paper.b / 2;
      left = std::min(left, x), right = std::max(right, x);
      top = std::min(top, y), bottom = std::max(bottom, y);
    }
  }
  EXPECT_GT(dark, 20);  // strokes more ink than paper
  EXPECT_GE(top, 11);   // the capitals' top row
  EXPECT_LE(top, 12);
  EXPECT_LE(bottom, 11 + 7);                     // no descenders in "D3 L0"
  EXPECT_NEAR((left + right) / 2.0, 21.5, 2.5);  // centred
  EXPECT_GT(right - left, 20);                   // five characters
}

TEST(Pictures, PagesCarryALegend) {
  // Legend lines are 10 pixels (scale 1 up to 640 columns), after 2 pixels of space: the gap,
  // unused, one display, the labels line, and 2 pixels below.
  const PipeserverPlan plan = pack_tiles(0, 100, 50, {tile(3, 40, 30)});
  const RgbImage page = framebuffer_page(plan);
  EXPECT_EQ(page.height(), 50 + 4 * 10 + 4);
  EXPECT_EQ(page.at(3, 52), (Rgb{255, 255, 255}));  // swatch: header gap
  EXPECT_EQ(page.at(3, 62), kUnused);               // swatch: unused
  EXPECT_EQ(page.at(3, 72), palette_colour(3));     // swatch: display 3
  EXPECT_EQ(page.at(3, 82), (Rgb{0, 0, 0}));        // the labels line has no swatch
  EXPECT_GT(page.width(), 100);                     // the longest line is wider than the picture

  const TileLayout layout = plan_layout(default_wall());
  const RgbImage wall = wall_page(layout);
  // 1300 columns: scale 2, lines of 20; 4 pipeservers, mullions, edges, labels.
  EXPECT_EQ(wall.height(), 980 + 7 * 20 + 8);
  EXPECT_EQ(wall.at(6, 980 + 4 + 3 * 20), palette_colour(3));
  EXPECT_EQ(wall.at(6, 980 + 4 + 4 * 20), kUnused);
}

TEST(Pictures, WallIsColouredByPipeserverAndShrunkWhenHuge) {
  const TileLayout small = plan_layout(default_wall());
  RgbImage pic = wall_picture(small);
  EXPECT_EQ(pic.width(), 1300);
  EXPECT_EQ(pic.height(), 980);
  EXPECT_EQ(pic.at(650, 200), kUnused);  // the vertical mullion
  const DisplayTile& t = small.tiles[0];
  EXPECT_EQ(pic.at(t.on_canvas.x + 3, t.on_canvas.y + 3), palette_colour(small.tile_pipeserver[0]));

  const TileLayout big = plan_layout(load_wall(std::string(L2_WALLS_DIR) + "/monitors-4x3.toml"));
  pic = wall_picture(big);  // 5240x3152 canvas, drawn at half size
  EXPECT_EQ(pic.width(), 2620);
  EXPECT_EQ(pic.height(), 1576);
  EXPECT_EQ(pic.at(650, 300), kUnused);  // canvas column 1300: mullion 1280..1319
  EXPECT_EQ(pic.at(100, 100), palette_colour(big.tile_pipeserver[0]));
}

TEST(TestFrame, TilesCarryThePatternAndEverythingElseIsBlackOrHeader) {
  const PipeserverPlan plan = pack_tiles(0, 30, 12, {tile(2, 10, 8), tile(4, 5, 3)});
  const RgbImage f = test_frame(plan, true);
  EXPECT_EQ(f.at(2, 0), test_pattern(2, 0, 0));
  EXPECT_EQ(f.at(11, 7), test_pattern(2, 9, 7));
  EXPECT_EQ(f.at(14, 2), test_pattern(4, 0, 2));
  EXPECT_EQ(f.at(14, 3), Rgb{});  // below the shorter tile
  EXPECT_EQ(f.at(25, 5), Rgb{});  // after END
  EXPECT_EQ(f.at(5, 10), Rgb{});  // below the last row
}

}  // namespace
}  // namespace l2
