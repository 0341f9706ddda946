#include "balance/balancer.hpp"

#include <algorithm>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_walls.hpp"

#include "tilelayout/planner.hpp"

namespace l2 {
namespace {

using test::strips_wall;

BalanceSettings strips(bool assign = false) {
  BalanceSettings s;
  s.mode = BalanceMode::Strips;
  s.assign = assign;
  s.motion = {1.0, 0};
  return s;
}

// The top-left tile at 3 per thousand pixels, the others at 1 (strip_edges_test's estimate).
const TileSeconds kHeavyTopLeft = {{7.5, 2.5}, {2.5, 2.5}};

TEST(Balancer, ModeNames) {
  EXPECT_EQ(parse_balance_mode("strips"), BalanceMode::Strips);
  EXPECT_EQ(parse_balance_mode("kd"), BalanceMode::Kd);
  EXPECT_EQ(parse_balance_mode("static"), BalanceMode::Static);
  EXPECT_EQ(parse_balance_mode("Strips"), std::nullopt);
  EXPECT_STREQ(to_string(BalanceMode::Kd), "kd");
}

TEST(Balancer, StripsMoveToTheCostAndKeepThePolicy) {
  Balancer b(strips_wall(), strips());
  ASSERT_EQ(b.layout().logical_tiles.size(), 4u);
  const BalanceStep step = b.next(kHeavyTopLeft);
  EXPECT_TRUE(step.changed);
  EXPECT_EQ(step.rejected, "");
  EXPECT_EQ(
      b.layout().logical_tiles,
      (std::vector<Rect>{{0, 0, 33, 38}, {33, 0, 67, 38}, {0, 38, 43, 62}, {43, 38, 57, 62}}));
  EXPECT_EQ(b.layout().tile_pipeserver, (std::vector<int>{0, 1, 0, 1}));
}

// Switched live (the control page): the next step cuts by the new mode, from even strips; back
// to static it plans the wall's own tiling again.
TEST(Balancer, ASwitchedModeCutsFromTheNextStep) {
  BalanceSettings fixed = strips();
  fixed.mode = BalanceMode::Static;
  Balancer b(strips_wall(), fixed);
  const std::vector<Rect> own = b.layout().logical_tiles;
  b.next(kHeavyTopLeft);
  EXPECT_EQ(b.layout().logical_tiles, own);  // static: nothing moves
  b.switch_mode(BalanceMode::Strips);
  EXPECT_EQ(b.settings().mode, BalanceMode::Strips);
  b.next(kHeavyTopLeft);
  EXPECT_EQ(
      b.layout().logical_tiles,
      (std::vector<Rect>{{0, 0, 33, 38}, {33, 0, 67, 38}, {0, 38, 43, 62}, {43, 38, 57, 62}}));
  b.switch_mode(BalanceMode::Static);
  b.next(kHeavyTopLeft);
  EXPECT_EQ(b.layout().logical_tiles, own);
}

TEST(Balancer, ASwitchToBalancingIsRefusedOnADepthWall) {
  Wall wall = strips_wall();
  wall.depth_layers = 2;
  BalanceSettings fixed;
  Balancer b(wall, fixed);
  try {
    b.switch_mode(BalanceMode::Kd);
    FAIL() << "kd accepted on a depth wall";
  } catch (const LayoutError& e) {
    EXPECT_EQ(std::string(e.what()),
              "balance.mode: kd needs a sort-first wall without [depth] or [overlay]");
  }
  EXPECT_EQ(b.settings().mode, BalanceMode::Static);
}

TEST(Balancer, AssignmentGivesTheHeaviestTileToTheFirstToFinish) {
  Balancer b(strips_wall(), strips(true));
  b.next(kHeavyTopLeft);
  // Predicted costs of the new tiles: 3.762, 3.838, 3.698, 3.702. 3.838 -> 0, 3.762 -> 1,
  // 3.702 -> 1 (at 3.762 it finishes first), 3.698 -> 0.
  EXPECT_EQ(b.layout().tile_pipeserver, (std::vector<int>{1, 0, 0, 1}));
}

TEST(Balancer, ALayoutThatDoesNotFitIsNotUsed) {
  // All the time in the top strip: its edge moves to row 25, and the bottom tiles, 75 rows,
  // do not fit a 64-row framebuffer.
  Balancer b(strips_wall(104, 64), strips());
  const std::vector<Rect> before = b.layout().logical_tiles;
  const BalanceStep step = b.next({{10, 0}, {10, 0}});
  EXPECT_FALSE(step.changed);
  EXPECT_THAT(step.rejected, testing::HasSubstr("does not fit the 104x64 framebuffer: needs 75 "
                                                "rows, 11 too many"));
  EXPECT_EQ(b.layout().logical_tiles, before);
  // The edges went back too: even times leave the even layout.
  const BalanceStep even = b.next({{1, 1}, {1, 1}});
  EXPECT_FALSE(even.changed);
  EXPECT_EQ(even.rejected, "");
}

TEST(Balancer, AFirstCutThatDoesNotFitLeavesTheWallsOwnPlan) {
  // Two 50x100 columns, one a pipeserver, fit 60-column framebuffers; the even strips, one
  // 100x50 strip a pipeserver, do not.
  Wall w = strips_wall(60, 110);
  w.tiling = {};
  w.tiling.kind = TilingKind::Grid;
  w.tiling.tile_width = 50;
  w.tiling.tile_height = 100;
  const Balancer b(w, strips());
  EXPECT_EQ(b.layout().logical_tiles, (std::vector<Rect>{{0, 0, 50, 100}, {50, 0, 50, 100}}));
  EXPECT_THAT(b.first_refused(), testing::HasSubstr("does not fit the 60x110 framebuffer"));
  EXPECT_EQ(Balancer(strips_wall(), strips()).first_refused(), "");
}

// A dead host: the next layout gives it nothing, its tiles counted at the others' mean cost
// per pixel (even times here, so the edges stay), and the planner's checks still hold.
TEST(Balancer, ALostPipeserversTilesGoToTheOthers) {
  Balancer b(strips_wall(), strips());
  b.lose_pipeserver(1);
  EXPECT_EQ(b.lost(), std::vector<int>{1});
  const BalanceStep step = b.next({{1, 1}, {}});
  EXPECT_TRUE(step.changed);
  EXPECT_EQ(
      b.layout().logical_tiles,
      (std::vector<Rect>{{0, 0, 50, 50}, {50, 0, 50, 50}, {0, 50, 50, 50}, {50, 50, 50, 50}}));
  EXPECT_EQ(b.layout().tile_pipeserver, (std::vector<int>{0, 0, 0, 0}));
  EXPECT_EQ(b.layout().pipeservers[0].tiles.size(), 4u);
  EXPECT_TRUE(b.layout().pipeservers[1].tiles.empty());
  // Later frames: its times (none) are not read.
  EXPECT_EQ(b.next({{1, 1, 1, 1}, {}}).rejected, "");
  EXPECT_TRUE(b.layout().pipeservers[1].tiles.empty());
}

TEST(Balancer, HeaviestFirstSharesALostPipeserversTilesAmongTheRest) {
  Wall w = strips_wall();
  w.pipeserver_count = 3;  // round-robin: tiles 0..3 to 0, 1, 2, 0
  Balancer b(w, strips(true));
  b.lose_pipeserver(2);
  b.next({{1, 1}, {1}, {1}});
  const std::vector<int>& of = b.layout().tile_pipeserver;
  EXPECT_EQ(std::count(of.begin(), of.end(), 2), 0);
  EXPECT_EQ(std::count(of.begin(), of.end(), 0), 2);
  EXPECT_EQ(std::count(of.begin(), of.end(), 1), 2);
}

// Refused at the loss, not a frame later: the run ends on it instead of saying it goes on.
TEST(Balancer, ALostPipeserverWhoseTilesDoNotFitTheOthersIsRefusedAtOnce) {
  Balancer b(strips_wall(104, 64), strips());  // two 50x50 tiles a framebuffer, one row
  try {
    b.lose_pipeserver(1);
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_THAT(e.what(),
                testing::StartsWith("the other pipeservers' framebuffers cannot hold pipeserver "
                                    "1's tiles: pipeserver 0: tile 2"));
  }
  EXPECT_TRUE(b.lost().empty());
  EXPECT_EQ(b.next({{1, 1}, {1, 1}}).rejected, "");
  EXPECT_FALSE(b.layout().pipeservers[1].tiles.empty());
}

// The re-cut strips do not fit the two left (a bottom strip taller than the 50-row
// framebuffers), the wall's own 2x2 does: it is the layout without the lost one.
TEST(Balancer, ALostPipeserversTilesFallBackToTheWallsTilingWhenTheReCutDoesNotFit) {
  Wall w = strips_wall(104, 50);  // two 50x50 tiles side by side a framebuffer
  w.pipeserver_count = 3;         // round-robin: tiles 0..3 to 0, 1, 2, 0
  Balancer b(w, strips());
  b.lose_pipeserver(2);
  const BalanceStep step = b.next({{7.5, 2.5}, {2.5}, {}});
  EXPECT_EQ(step.rejected, "");
  EXPECT_EQ(
      b.layout().logical_tiles,
      (std::vector<Rect>{{0, 0, 50, 50}, {50, 0, 50, 50}, {0, 50, 50, 50}, {50, 50, 50, 50}}));
  EXPECT_TRUE(b.layout().pipeservers[2].tiles.empty());
  EXPECT_EQ(b.layout().pipeservers[0].tiles.size(), 2u);
  EXPECT_EQ(b.layout().pipeservers[1].tiles.size(), 2u);
}

TEST(Balancer, TheLastPipeserverCannotBeLost) {
  Balancer b(strips_wall(), strips());
  EXPECT_THROW(b.lose_pipeserver(2), std::invalid_argument);
  b.lose_pipeserver(0);
  try {
    b.lose_pipeserver(1);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "pipeserver 1 was the last one rendering: no pipeserver is left");
  }
}

TEST(Balancer, KdRecutsOverTheMeasuredGrid) {
  Wall w = strips_wall();
  w.tiling = {};
  w.tiling.kind = TilingKind::KdSplit;
  w.tiling.tile_count = 2;
  BalanceSettings s;
  s.mode = BalanceMode::Kd;
  s.motion = {1.0, 0};
  s.kd_grid_columns = 4;
  s.kd_grid_rows = 1;
  Balancer b(w, s);
  ASSERT_EQ(b.layout().logical_tiles, (std::vector<Rect>{{0, 0, 50, 100}, {50, 0, 50, 100}}));
  // Cells of 25 columns cost 1.5, 1.5, 0.5, 0.5: half of 4 at 25 + 25 / 3 = 33.3.
  EXPECT_TRUE(b.next({{3}, {1}}).changed);
  EXPECT_EQ(b.layout().logical_tiles, (std::vector<Rect>{{0, 0, 33, 100}, {33, 0, 67, 100}}));
}

TEST(Balancer, StaticKeepsTheWallsLayout) {
  Balancer b(strips_wall(), {});
  const TileLayout planned = plan_layout(strips_wall());
  EXPECT_FALSE(b.next(kHeavyTopLeft).changed);
  EXPECT_EQ(b.layout().logical_tiles, planned.logical_tiles);
}

TEST(Balancer, RefusesADepthWall) {
  Wall w = strips_wall();
  w.depth_layers = 2;
  try {
    Balancer b(w, strips());
    FAIL() << "a depth wall was balanced";
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(),
                 "balance.mode: strips needs a sort-first wall without [depth] or "
                 "[overlay]");
  }
}

// Resistance: timing noise of up to 8 % a tile on an even load. Without it the edges chase the
// noise; with it (10 %) no step is predicted to pay, and the layout stays.
TileSeconds noisy_even(int frame) {
  static constexpr double kNoise[] = {0.08, -0.05, 0.02, -0.08, 0.06, -0.03, 0.07, -0.06};
  TileSeconds t = {{2.5, 2.5}, {2.5, 2.5}};
  for (int i = 0; i < 4; ++i) t[i / 2][i % 2] *= 1 + kNoise[(frame + 3 * i) % 8];
  return t;
}

BalanceSettings resisting(double resistance) {
  BalanceSettings s = strips();
  s.motion = {};  // the default gain and dead band
  s.resistance = resistance;
  return s;
}

TEST(Balancer, ResistanceKeepsNoiseFromMovingEdges) {
  Balancer chasing(strips_wall(), resisting(0));
  int moves = 0;
  for (int k = 0; k < 40; ++k) moves += chasing.next(noisy_even(k)).changed ? 1 : 0;
  EXPECT_GT(moves, 5);
  Balancer b(strips_wall(), resisting(0.1));
  const std::vector<Rect> own = b.layout().logical_tiles;
  for (int k = 0; k < 40; ++k) {
    const BalanceStep step = b.next(noisy_even(k));
    EXPECT_FALSE(step.changed) << k;
    EXPECT_GT(step.predicted_ratio, 0.9) << k;
  }
  EXPECT_EQ(b.layout().logical_tiles, own);
}

TEST(Balancer, ResistanceStillMovesEdgesForARealImbalance) {
  // kHeavyTopLeft: pipeserver 0 takes 10 of 15 s. Half-way to balance the strips give it 8.75
  // and pipeserver 1 6.25 (strip_edges_test's cut): 0.875 of the frame, a gain of 12.5 %.
  Balancer b(strips_wall(), resisting(0.1));
  const BalanceStep step = b.next(kHeavyTopLeft);
  EXPECT_TRUE(step.changed);
  EXPECT_FALSE(step.resisted);
  EXPECT_NEAR(step.predicted_ratio, 0.875, 0.01);
  // The same move against a resistance of 20 % does not pay.
  Balancer stiff(strips_wall(), resisting(0.2));
  const BalanceStep held = stiff.next(kHeavyTopLeft);
  EXPECT_FALSE(held.changed);
  EXPECT_TRUE(held.resisted);
  EXPECT_NEAR(held.predicted_ratio, 0.875, 0.01);
}

// Two 50x100 displays side by side, a tile each, one pipeserver each. Strips cut across both
// displays: two display tiles a pipeserver instead of one.
Wall two_displays() {
  Wall w = strips_wall();
  Display right = w.displays[0];
  w.displays[0].width = 50;
  right.id = 1;
  right.canvas_x = 50;
  right.width = 50;
  w.displays.push_back(right);
  w.tiling = {};
  w.tiling.kind = TilingKind::Grid;
  w.tiling.tile_width = 50;
  w.tiling.tile_height = 100;
  return w;
}

TEST(Balancer, ResistanceCountsWhatMoreTilesCost) {
  // Pipeserver 0's display costs 6 s, pipeserver 1's 4 s. Even horizontal strips give each 5
  // by pixels: a gain of a sixth. With a fifth of the mean tile (1 s) fixed a display tile, the
  // strips' four tiles cost each pipeserver 4 + 2 x 1 = 6 s: nothing gained, not taken.
  BalanceSettings s = resisting(0.1);
  Balancer by_pixels(two_displays(), s);
  ASSERT_EQ(by_pixels.layout().tiles.size(), 2u);
  const BalanceStep moved = by_pixels.next({{6}, {4}});
  EXPECT_TRUE(moved.changed);
  EXPECT_DOUBLE_EQ(moved.predicted_ratio, 5.0 / 6);
  EXPECT_EQ(by_pixels.layout().tiles.size(), 4u);
  s.tile_cost = 0.2;
  Balancer counted(two_displays(), s);
  const BalanceStep held = counted.next({{6}, {4}});
  EXPECT_FALSE(held.changed);
  EXPECT_TRUE(held.resisted);
  EXPECT_DOUBLE_EQ(held.predicted_ratio, 1);
  EXPECT_EQ(counted.layout().tiles.size(), 2u);
}

TEST(Balancer, ALostPipeserverMovesTilesWhateverTheResistance) {
  Balancer b(strips_wall(), resisting(0.5));
  b.lose_pipeserver(1);
  EXPECT_TRUE(b.next({{1, 1}, {}}).changed);
  EXPECT_TRUE(b.layout().pipeservers[1].tiles.empty());
}

// What the wall's own layout would have taken on a frame measured on the balanced one: the
// summary's answer to whether balancing paid.
TEST(Balancer, PredictsAnotherLayoutAtTheCostsMeasured) {
  Balancer b(strips_wall(), strips());
  const TileLayout own = plan_layout(strips_wall());
  EXPECT_DOUBLE_EQ(b.predicted(b.layout(), kHeavyTopLeft).slowest, 10);  // 7.5 + 2.5 measured
  EXPECT_DOUBLE_EQ(b.predicted(own, kHeavyTopLeft).slowest, 10);         // the same tiles
  EXPECT_DOUBLE_EQ(b.predicted(own, kHeavyTopLeft).work, 15);            // 7.5 + 2.5 + 2.5 + 2.5
  b.next(kHeavyTopLeft);  // the strips moved toward the heavy tile
  // Even times measured on the moved strips: on them the prediction is what was measured.
  const TileSeconds even = {{2.5, 2.5}, {2.5, 2.5}};
  EXPECT_DOUBLE_EQ(b.predicted(b.layout(), even).slowest, 5);
}

TEST(Balancer, ResistanceAndTileCostAreFractions) {
  BalanceSettings s = strips();
  s.resistance = 1;
  EXPECT_THROW(Balancer(strips_wall(), s), std::invalid_argument);
  s.resistance = 0.1;
  s.tile_cost = -0.1;
  EXPECT_THROW(Balancer(strips_wall(), s), std::invalid_argument);
}

}  // namespace
}  // namespace l2
