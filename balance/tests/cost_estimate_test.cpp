#include "balance/cost_estimate.hpp"

#include <gtest/gtest.h>

#include "tilelayout/planner.hpp"

namespace l2 {
namespace {

// Two 10x10 patches side by side: 1 and 3 per pixel, 100 + 300 in all.
CostEstimate two_patches() {
  return CostEstimate({{{0, 0, 10, 10}, 1}, {{10, 0, 10, 10}, 3}});
}

TEST(CostEstimate, CostOfARectangleSumsThePatchesItOverlaps) {
  const CostEstimate e = two_patches();
  EXPECT_DOUBLE_EQ(e.total(), 400);
  EXPECT_DOUBLE_EQ(e.cost({5, 0, 10, 10}), 50 + 150);
  EXPECT_DOUBLE_EQ(e.cost({30, 30, 5, 5}), 0);
}

TEST(CostEstimate, CutXIsExactBetweenPatchEdges) {
  // Half of 400: the left patch gives 100, then 30 per column: 10 + 100/30.
  EXPECT_DOUBLE_EQ(two_patches().cut_x({0, 0, 20, 10}, 200), 10 + 100.0 / 30);
  // Within the left patch alone: 10 per column.
  EXPECT_DOUBLE_EQ(two_patches().cut_x({0, 0, 20, 10}, 55), 5.5);
}

TEST(CostEstimate, CutYWithinABand) {
  // 40 per row over the full width; the band's top is row 2.
  EXPECT_DOUBLE_EQ(two_patches().cut_y({0, 2, 20, 8}, 100), 2 + 2.5);
  // Only the right patch's columns: 30 per row.
  EXPECT_DOUBLE_EQ(two_patches().cut_y({10, 0, 10, 10}, 150), 5);
}

TEST(CostEstimate, NothingMeasuredCutsByArea) {
  const CostEstimate e({{{0, 0, 10, 10}, 0}, {{10, 0, 10, 10}, 0}});
  EXPECT_DOUBLE_EQ(e.total(), 200);
  EXPECT_DOUBLE_EQ(e.cut_x({0, 0, 20, 10}, 50), 5);
}

Wall two_tile_wall() {
  Wall w;
  Display d;
  d.width = 100;
  d.height = 50;
  w.displays = {d};
  w.canvas_width = 100;
  w.canvas_height = 50;
  w.tiling.kind = TilingKind::List;
  w.tiling.rects = {{0, 0, 50, 50}, {50, 0, 50, 50}};
  w.pipeserver_count = 2;
  w.framebuffer_width = 128;
  w.framebuffer_height = 64;
  return w;
}

TEST(CostEstimate, FromLayoutSpreadsEachTilesTimeOverItsPixels) {
  const TileLayout layout = plan_layout(two_tile_wall());
  const CostEstimate e = CostEstimate::from_layout(layout, {{1.0}, {3.0}});
  EXPECT_DOUBLE_EQ(e.total(), 4.0);
  EXPECT_DOUBLE_EQ(e.cost({25, 0, 50, 50}), 0.5 + 1.5);
}

TEST(CostEstimate, FromLayoutRefusesTimesOfAnotherShape) {
  const TileLayout layout = plan_layout(two_tile_wall());
  EXPECT_THROW(CostEstimate::from_layout(layout, {{1.0}}), std::invalid_argument);
  EXPECT_THROW(CostEstimate::from_layout(layout, {{1.0}, {1.0, 2.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace l2
