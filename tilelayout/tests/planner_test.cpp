#include "tilelayout/planner.hpp"

#include <gtest/gtest.h>

#include "tilelayout/coverage.hpp"
#include "tilelayout/fit.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

Display display(int id, int x, int y, int w, int h) {
  Display d;
  d.id = id;
  d.canvas_x = x;
  d.canvas_y = y;
  d.width = w;
  d.height = h;
  return d;
}

Wall wall_of(std::vector<Display> displays, int canvas_w, int canvas_h) {
  Wall w;
  w.displays = std::move(displays);
  w.canvas_width = canvas_w;
  w.canvas_height = canvas_h;
  return w;
}

TEST(Tiling, GridClipsTheLastColumnAndRow) {
  Wall w = wall_of({display(0, 0, 0, 210, 80)}, 210, 80);
  w.tiling.kind = TilingKind::Grid;
  w.tiling.tile_width = 50;
  w.tiling.tile_height = 40;
  const auto tiles = make_logical_tiles(w);
  ASSERT_EQ(tiles.size(), 10u);
  EXPECT_EQ(tiles[0], (Rect{0, 0, 50, 40}));
  EXPECT_EQ(tiles[4], (Rect{200, 0, 10, 40}));
  EXPECT_EQ(tiles[5], (Rect{0, 40, 50, 40}));
  EXPECT_EQ(tiles[9], (Rect{200, 40, 10, 40}));
}

TEST(Tiling, StripsAreHorizontalBandsCutIntoColumns) {
  Wall w = wall_of({display(0, 0, 0, 10, 7)}, 10, 7);
  w.tiling.kind = TilingKind::Strips;
  w.tiling.strip_count = 2;
  w.tiling.substrip_count = 3;
  EXPECT_EQ(
      make_logical_tiles(w),
      (std::vector<Rect>{
          {0, 0, 3, 3}, {3, 0, 3, 3}, {6, 0, 4, 3}, {0, 3, 3, 4}, {3, 3, 3, 4}, {6, 3, 4, 4}}));
}

TEST(Tiling, KdUniformCutsLongerSideInHalves) {
  Wall w = wall_of({display(0, 0, 0, 400, 300)}, 400, 300);
  w.tiling.kind = TilingKind::KdSplit;
  w.tiling.tile_count = 4;
  EXPECT_EQ(make_logical_tiles(w),
            (std::vector<Rect>{
                {0, 0, 200, 150}, {0, 150, 200, 150}, {200, 0, 200, 150}, {200, 150, 200, 150}}));
}

TEST(Tiling, KdFollowsTheCostGrid) {
  // Cost 1 on the left half, 3 on the right: total 80000, half of it is reached 66.7 columns
  // into the right half.
  Wall w = wall_of({display(0, 0, 0, 400, 100)}, 400, 100);
  w.tiling.kind = TilingKind::KdSplit;
  w.tiling.tile_count = 2;
  w.tiling.cost = {{1, 3}};
  EXPECT_EQ(make_logical_tiles(w), (std::vector<Rect>{{0, 0, 267, 100}, {267, 0, 133, 100}}));
}

TEST(Tiling, KdIgnoresWhatMullionsHide) {
  // Two 100x100 displays, 50 pixels apart: half the visible cost is all of display 0.
  Wall w = wall_of({display(0, 0, 0, 100, 100), display(1, 150, 0, 100, 100)}, 250, 100);
  w.tiling.kind = TilingKind::KdSplit;
  w.tiling.tile_count = 2;
  const auto tiles = make_logical_tiles(w);
  EXPECT_EQ(tiles, (std::vector<Rect>{{0, 0, 100, 100}, {100, 0, 150, 100}}));
  const auto parts = split_at_displays(w, tiles);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[1].display, 1);
  EXPECT_EQ(parts[1].on_display, (Rect{0, 0, 100, 100}));
  EXPECT_EQ(parts[1].on_canvas, (Rect{150, 0, 100, 100}));
  EXPECT_EQ(parts[1].logical_tile, 1);
}

TEST(Tiling, KdReportsTileCountsThatCannotBeCut) {
  Wall w = wall_of({display(0, 0, 0, 3, 3)}, 3, 3);
  w.source = "k.toml";
  w.tiling_line = 7;
  w.tiling.kind = TilingKind::KdSplit;
  w.tiling.tile_count = 9;
  try {
    make_logical_tiles(w);
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(), "k.toml:7: tiling.tile_count: cannot cut 9 tiles out of 3x3 at 0,0");
  }
}

TEST(SplitAtDisplays, DropsMullionsAndDuplicatesProjectorOverlap) {
  // Display 1 starts 10 pixels right of display 0 (a mullion); display 2 overlaps display 1.
  const Wall w =
      wall_of({display(0, 0, 0, 100, 50), display(1, 110, 0, 100, 50), display(2, 190, 0, 100, 50)},
              290, 50);
  const auto parts = split_at_displays(w, {{90, 10, 120, 20}});
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(parts[0].display, 0);
  EXPECT_EQ(parts[0].on_display, (Rect{90, 10, 10, 20}));
  EXPECT_EQ(parts[1].display, 1);
  EXPECT_EQ(parts[1].on_display, (Rect{0, 10, 100, 20}));
  EXPECT_EQ(parts[2].display, 2);
  EXPECT_EQ(parts[2].on_display, (Rect{0, 10, 20, 20}));
  EXPECT_EQ(parts[2].on_canvas, (Rect{190, 10, 20, 20}));
  EXPECT_TRUE(split_at_displays(w, {{100, 0, 10, 50}}).empty());  // all behind the mullion
}

std::vector<Rect> grid(int columns, int rows) {
  std::vector<Rect> out;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) out.push_back({c * 10, r * 10, 10, 10});
  }
  return out;
}

std::vector<int> assign(AssignmentPolicy p, const std::vector<Rect>& tiles, int pipeservers,
                        std::vector<long long> weights = {}) {
  if (weights.empty()) weights.assign(tiles.size(), 100);
  const Rect canvas{0, 0, tiles.back().right(), tiles.back().bottom()};
  return assign_pipeservers(p, tiles, weights, pipeservers, canvas);
}

TEST(Assignment, RoundRobinZigZagBlocks) {
  const auto tiles = grid(4, 2);
  EXPECT_EQ(assign(AssignmentPolicy::RoundRobin, tiles, 3),
            (std::vector<int>{0, 1, 2, 0, 1, 2, 0, 1}));
  // Row 0 left to right: 0 1 2 0; row 1 right to left continues 1 2 0 1 from tile 7.
  EXPECT_EQ(assign(AssignmentPolicy::ZigZag, tiles, 3), (std::vector<int>{0, 1, 2, 0, 1, 0, 2, 1}));
  EXPECT_EQ(assign(AssignmentPolicy::Blocks, tiles, 3), (std::vector<int>{0, 0, 0, 1, 1, 1, 2, 2}));
}

TEST(Assignment, SpiralStartsInTheCentreAndTurnsClockwise) {
  // 3x3 grid, 9 pipeservers: the pipeserver number is the position in the spiral.
  EXPECT_EQ(assign(AssignmentPolicy::Spiral, grid(3, 3), 9),
            (std::vector<int>{1, 2, 3, 8, 0, 4, 7, 6, 5}));
}

TEST(Assignment, AreaBalancedGivesTheLargestTileToTheLeastLoaded) {
  // Largest first: t5(6)->s0, t0(5)->s1, t2(4)->s2, t3(3)->s2, t4(2)->s1, t1(1)->s0,
  // then loads are 7,7,7: t6->s0, t7->s1.
  EXPECT_EQ(assign(AssignmentPolicy::AreaBalanced, grid(4, 2), 3, {5, 1, 4, 3, 2, 6, 1, 1}),
            (std::vector<int>{1, 0, 2, 2, 1, 0, 0, 1}));
}

const std::string kListWall =
    "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 100\nheight = 80\n"
    "[tiling]\nkind = \"list\"\ntiles = [[0, 0, 100, 20], [0, 20, 60, 60]]\n"
    "[pipeservers]\ncount = 2\nframebuffer_width = 200\nframebuffer_height = 100\n";

TEST(Planner, WarnsAboutUncoveredCanvasWithTheArea) {
  const TileLayout layout = plan_layout(parse_wall(kListWall, "walls/t.toml"));
  EXPECT_EQ(layout.warnings, (std::vector<std::string>{
                                 "walls/t.toml: warning: canvas area 40x60 at 60,20 (display 0: "
                                 "2400 pixels) is not covered by any tile"}));
  const auto cov = display_coverage(layout.wall, layout.tiles);
  EXPECT_EQ(cov[0].covered, 2000 + 3600);
  EXPECT_EQ(cov[0].overlapped, 0);
}

TEST(Planner, PacksEachPipeserversTilesTallestFirst) {
  const TileLayout layout = plan_layout(parse_wall(
      "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 100\nheight = 80\n"
      "[tiling]\nkind = \"list\"\ntiles = [[0, 0, 50, 10], [50, 0, 50, 80], [0, 10, 50, 70]]\n"
      "[pipeservers]\ncount = 1\nframebuffer_width = 200\nframebuffer_height = 100\n",
      "p.toml"));
  ASSERT_EQ(layout.pipeservers.size(), 1u);
  const PipeserverPlan& s = layout.pipeservers[0];
  ASSERT_EQ(s.tiles.size(), 3u);
  EXPECT_EQ(s.tiles[0].tile.logical_tile, 1);  // 80 tall
  EXPECT_EQ(s.tiles[1].tile.logical_tile, 2);  // 70 tall
  EXPECT_EQ(s.tiles[2].tile.logical_tile, 0);  // 10 tall
  EXPECT_EQ(s.tiles[2].fb_x, 2 + 50 + 2 + 50 + 2);
  EXPECT_EQ(layout.tile_pipeserver, (std::vector<int>{0, 0, 0}));
  EXPECT_TRUE(layout.warnings.empty());
}

TEST(Planner, PackingErrorsNameFileLineServerAndTile) {
  try {
    plan_layout(
        parse_wall("[display_grid]\ncolumns = 1\nrows = 1\nwidth = 100\nheight = 80\n"
                   "[tiling]\nkind = \"grid\"\ntile_width = 100\ntile_height = 40\n"
                   "[pipeservers]\ncount = 1\nframebuffer_width = 200\nframebuffer_height = 60\n",
                   "walls/small.toml"));
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(),
                 "walls/small.toml:13: pipeserver 0: tile 1 (display 0, 100x40 at 0,40) does not "
                 "fit the 200x60 framebuffer: needs 80 rows, 20 too many; what would fit, each "
                 "alone: [tiling] tile_width = 87 with tile_height = 30; framebuffer_width = 204; "
                 "framebuffer_height = 80; pipeservers.count = 2");
  }
}

// Four tiles of 200 and 100 columns, dealt round-robin to two 310x100 framebuffers: pipeserver
// 0 gets both 200-column tiles (202 + 202 columns with their gaps: two rows, 200 rows). What
// fits instead, worked out by hand: 200 rows; or 404 columns (one row); or blocks (0,1 | 2,3)
// or area-balanced (0,1 | 2,3: largest first, ties to the lower pipeserver), 304 columns each;
// not zig-zag (one tile row: round-robin again) nor spiral (ring 0: tile 1, ring 1 clockwise
// from the top-left: 2, 3, 0, so pipeserver 1 gets 2 and 0); or 3 pipeservers (0,3 | 1 | 2).
constexpr const char* kTightWall = R"(name = "four tiles, two pipeservers"
[display_grid]
columns = 1
rows = 1
width = 600
height = 100
[tiling]
kind = "list"
tiles = [[0, 0, 200, 100], [200, 0, 100, 100], [300, 0, 200, 100], [500, 0, 100, 100]]
[pipeservers]
count = 2
framebuffer_width = 310
framebuffer_height = 100
)";

TEST(Planner, TilesThatDoNotFitSayWhatWould) {
  const Wall wall = parse_wall(kTightWall, "walls/tight.toml");
  const FitSuggestions fit = suggest_fit(wall);
  EXPECT_FALSE(fit.fits);
  EXPECT_EQ(fit.height_at_width, 200);
  EXPECT_EQ(fit.width_at_height, 404);
  // 202 columns hold one 200-column tile a row: two rows of 100 on both pipeservers (pipeserver
  // 1's 102 + 102 columns do not fit 202 either); 202 x 200 = 404 x 100, the narrower kept.
  EXPECT_EQ(fit.smallest, (std::pair{202, 200}));
  EXPECT_EQ(fit.policies, (std::vector<AssignmentPolicy>{AssignmentPolicy::Blocks,
                                                         AssignmentPolicy::AreaBalanced}));
  EXPECT_EQ(fit.pipeserver_count, 3);
  EXPECT_EQ(suggestion_lines(wall, fit),
            (std::vector<std::string>{
                "as written (310x100, 2 pipeservers, round-robin): does not fit",
                "framebuffer_height = 200 (at framebuffer_width = 310)",
                "framebuffer_width = 404 (at framebuffer_height = 100)",
                "framebuffer_width = 202, framebuffer_height = 200: the smallest framebuffer",
                "assignment = \"blocks\" (at 310x100, 2 pipeservers)",
                "assignment = \"area-balanced\" (at 310x100, 2 pipeservers)",
                "pipeservers.count = 3 (at 310x100, round-robin): the fewest that fit"}));
  // The error's hint puts the best fit first: the fewest framebuffer pixels in all, worked out
  // by hand: a policy keeps 2 x 310x100 = 62,000; width 404, 80,800; 3 pipeservers, 93,000;
  // height 200, 124,000 (issue 56: more pipeservers than needed came before a better height).
  try {
    plan_layout(wall);
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(),
                 "walls/tight.toml:13: pipeserver 0: tile 1 (display 0, 200x100 at 300,0) does not "
                 "fit the 310x100 framebuffer: needs 200 rows, 100 too many; what would fit, each "
                 "alone: assignment = \"blocks\" or \"area-balanced\"; framebuffer_width = 404; "
                 "pipeservers.count = 3; framebuffer_height = 200");
  }
  // Each suggestion, applied alone, plans.
  Wall w = wall;
  w.framebuffer_height = 200;
  EXPECT_NO_THROW(plan_layout(w));
  w = wall;
  w.framebuffer_width = 404;
  EXPECT_NO_THROW(plan_layout(w));
  w = wall;
  w.assignment = AssignmentPolicy::Blocks;
  EXPECT_NO_THROW(plan_layout(w));
  w = wall;
  w.pipeserver_count = 3;
  EXPECT_NO_THROW(plan_layout(w));
  w = wall;
  w.framebuffer_height = 199;
  EXPECT_THROW(plan_layout(w), LayoutError);
  w = wall;
  w.framebuffer_width = 403;
  EXPECT_THROW(plan_layout(w), LayoutError);
}

TEST(Planner, GivenAssignmentReplacesThePolicy) {
  const char* kWall =
      "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 100\nheight = 80\n"
      "[tiling]\nkind = \"grid\"\ntile_width = 50\ntile_height = 80\n"
      "[pipeservers]\ncount = 2\nframebuffer_width = 200\nframebuffer_height = 100\n";
  const TileLayout layout = plan_layout(parse_wall(kWall, "g.toml"), {1, 0});
  EXPECT_EQ(layout.tile_pipeserver, (std::vector<int>{1, 0}));
  ASSERT_EQ(layout.pipeservers[0].tiles.size(), 1u);
  EXPECT_EQ(layout.pipeservers[0].tiles[0].tile.logical_tile, 1);
  try {
    plan_layout(parse_wall(kWall, "g.toml"), {0, 2});
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(), "g.toml: assigned pipeserver 2 is not 0..1");
  }
  try {
    plan_layout(parse_wall(kWall, "g.toml"), {0});
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(),
                 "g.toml: a given assignment needs a sort-first wall without overlay and one "
                 "pipeserver for each of its 2 logical tiles, got 1");
  }
}

// A live run's host that died: the others take its tiles, and it alone may have none.
TEST(Planner, GonePipeserverTakesNoTiles) {
  const char* kWall =
      "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 100\nheight = 80\n"
      "[tiling]\nkind = \"grid\"\ntile_width = 50\ntile_height = 80\n"
      "[pipeservers]\ncount = 3\nframebuffer_width = 200\nframebuffer_height = 100\n";
  const Wall wall = parse_wall(kWall, "g.toml");
  const TileLayout layout = plan_layout(wall, {2, 0}, {1});
  ASSERT_EQ(layout.pipeservers.size(), 3u);
  EXPECT_TRUE(layout.pipeservers[1].tiles.empty());
  EXPECT_EQ(layout.pipeservers[1].pipeserver, 1);
  ASSERT_EQ(layout.pipeservers[2].tiles.size(), 1u);
  EXPECT_EQ(layout.pipeservers[2].tiles[0].tile.logical_tile, 0);
  try {
    plan_layout(wall, {1, 0}, {1});
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(), "g.toml: pipeserver 1 is gone but was given logical tile 0");
  }
  try {
    plan_layout(wall, {0, 1}, {3});
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(), "g.toml: gone pipeserver 3 is not 0..2");
  }
  // Only the gone one may go without: pipeserver 2 still needs a tile.
  try {
    plan_layout(wall, {0, 0}, {1});
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_NE(std::string(e.what()).find("pipeserver 2 gets no tiles"), std::string::npos)
        << e.what();
  }
}

// Grid tiles scaled down in eighths, worked out by hand. The 100x80 display in 100x40 tiles
// needs 80 rows of a 200x60 framebuffer; 87x30 tiles (seven eighths across, six down) are six
// tiles: 87+13 columns by 30+30+20 rows, packed as 89+15+89 columns (30 rows) and 15+89+15 (30):
// 60 rows. No larger eighth fits: 100x30 and 100x35 keep one 100-column tile a row (80 rows),
// 75x35 and 87x35 need 70 rows. The idle wall's one 320x240 tile as 320x210 is two tiles, one
// each (280x240 is as large, found later).
TEST(Planner, AGridWallIsToldATileSizeThatFits) {
  const FitSuggestions fit = suggest_fit(
      parse_wall("[display_grid]\ncolumns = 1\nrows = 1\nwidth = 100\nheight = 80\n"
                 "[tiling]\nkind = \"grid\"\ntile_width = 100\ntile_height = 40\n"
                 "[pipeservers]\ncount = 1\nframebuffer_width = 200\nframebuffer_height = 60\n",
                 "walls/small.toml"));
  EXPECT_EQ(fit.grid_tile, (std::pair{87, 30}));
  Wall w = parse_wall(
      "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 100\nheight = 80\n"
      "[tiling]\nkind = \"grid\"\ntile_width = 87\ntile_height = 30\n"
      "[pipeservers]\ncount = 1\nframebuffer_width = 200\nframebuffer_height = 60\n",
      "walls/small.toml");
  EXPECT_NO_THROW(plan_layout(w));  // the suggestion, applied, plans
}

// A framebuffer side past the board's input limit needs the [mesh] limit raised with it: the
// hint says both, so that following it does not end in a second refusal.
TEST(Planner, AFramebufferPastTheBoardLimitComesWithTheLimit) {
  const std::string toml =
      "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 1200\nheight = 1080\n"
      "[tiling]\nkind = \"grid\"\ntile_width = 1200\ntile_height = 1080\n"
      "[pipeservers]\ncount = 1\nframebuffer_width = 1204\nframebuffer_height = 1000\n";
  try {
    plan_layout(parse_wall(toml, "walls/tall.toml"));
    FAIL();
  } catch (const LayoutError& e) {
    const std::string what = e.what();
    const std::string hint =
        "what would fit, each alone: framebuffer_height = 1080 with [mesh] board_max_height = "
        "1080";
    EXPECT_EQ(what.substr(what.size() - std::min(what.size(), hint.size())), hint) << what;
  }
  Wall w = parse_wall(toml, "walls/tall.toml");
  w.framebuffer_height = 1080;
  w.board_max_height = 1080;
  EXPECT_NO_THROW(plan_layout(w));
}

TEST(Planner, PipeserverWithoutTilesIsRefused) {
  try {
    plan_layout(
        parse_wall("[display_grid]\ncolumns = 1\nrows = 1\nwidth = 320\nheight = 240\n"
                   "[tiling]\nkind = \"grid\"\ntile_width = 320\ntile_height = 240\n"
                   "[pipeservers]\ncount = 2\nframebuffer_width = 400\n"
                   "framebuffer_height = 300\n",
                   "walls/idle.toml"));
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(),
                 "walls/idle.toml: pipeserver 1 gets no tiles (1 display tiles for 2 "
                 "pipeservers); every pipeserver needs a tile (one without scans out idle frames, "
                 "which never earn READY); what would fit, each alone: pipeservers.count = 1; "
                 "[tiling] tile_width = 320 with tile_height = 210");
  }
}

}  // namespace
}  // namespace l2

namespace l2 {
namespace {

TEST(Planner, TilesTooLargeEitherWayNeedBothSides) {
  // Two 250x250 tiles on one 100x100 framebuffer: too narrow and too low. 252 columns hold one
  // tile a row, two rows of 250.
  try {
    plan_layout(
        parse_wall("[display_grid]\ncolumns = 1\nrows = 1\nwidth = 250\nheight = 500\n"
                   "[tiling]\nkind = \"grid\"\ntile_width = 250\ntile_height = 250\n"
                   "[pipeservers]\ncount = 1\nframebuffer_width = 100\n"
                   "framebuffer_height = 100\n",
                   "walls/big.toml"));
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(),
                 "walls/big.toml:13: pipeserver 0: tile 0 (display 0, 250x250 at 0,0) does not "
                 "fit the 100x100 framebuffer: needs 252 columns, 152 too many; what would fit, "
                 "each alone: framebuffer_width = 252 with framebuffer_height = 500");
  }
}

}  // namespace
}  // namespace l2
