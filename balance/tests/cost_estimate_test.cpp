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

TEST(CostEstimate, CutsXAreExactBetweenPatchEdges) {
  // Half of 400: the left patch gives 100, then 30 per column: 10 + 100/30.
  const std::vector<double> halves = two_patches().cuts_x({0, 0, 20, 10}, 2);
  ASSERT_EQ(halves.size(), 1u);
  EXPECT_DOUBLE_EQ(halves[0], 10 + 100.0 / 30);
  // Within the left patch alone: 10 per column.
  EXPECT_EQ(two_patches().cuts_x({0, 0, 10, 10}, 4), (std::vector<double>{2.5, 5, 7.5}));
  EXPECT_TRUE(two_patches().cuts_x({0, 0, 10, 10}, 1).empty());
}

TEST(CostEstimate, CutsYWithinABand) {
  // 40 per row over the full width; the band's top is row 2: 160 in rows 2..6.
  EXPECT_EQ(two_patches().cuts_y({0, 2, 20, 8}, 2), (std::vector<double>{6}));
  // Only the right patch's columns: 30 per row.
  EXPECT_EQ(two_patches().cuts_y({10, 0, 10, 10}, 2), (std::vector<double>{5}));
}

TEST(CostEstimate, NothingMeasuredCutsByArea) {
  const CostEstimate e({{{0, 0, 10, 10}, 0}, {{10, 0, 10, 10}, 0}});
  EXPECT_DOUBLE_EQ(e.total(), 200);
  EXPECT_EQ(e.cuts_x({0, 0, 20, 10}, 4), (std::vector<double>{5, 10, 15}));
}

// 10 per column over 20 columns, and ten batches of 10 triangles at columns 10..13, each
// triangle priced 1 in every rectangle its footprint touches: 200 + 100 drawn once.
CostEstimate cloud_at_column_10() {
  Footprints cloud(10, BatchFootprint{{10, 0, 4, 10}, 10});
  return CostEstimate({{{0, 0, 20, 10}, 1}}, cloud, 1);
}

TEST(CostEstimate, EveryRectangleAFootprintTouchesPaysAllOfIt) {
  const CostEstimate e = cloud_at_column_10();
  EXPECT_DOUBLE_EQ(e.total(), 300);
  EXPECT_DOUBLE_EQ(e.cost({0, 0, 10, 10}), 100);       // beside the cloud: pixels alone
  EXPECT_DOUBLE_EQ(e.cost({10, 0, 1, 10}), 10 + 100);  // one column of it: all its batches
  EXPECT_DOUBLE_EQ(e.cost({11, 0, 9, 10}), 90 + 100);  // and the rest of it: again
  EXPECT_DOUBLE_EQ(e.cost({0, 0, 20, 10}), e.total());
}

TEST(CostEstimate, CutsLeaveACloudWholeWhenCuttingThroughCostsMore) {
  // Cutting through the cloud (10 < c < 14) makes both halves pay its 100; by pixels and
  // the cloud spread over its columns, half of 300 falls at 11.43 (left 214 then, right 186).
  // Cutting at its left edge, the right half pays 100 + 100, the left 100: the largest part
  // is as cheap as it gets.
  const std::vector<double> halves = cloud_at_column_10().cuts_x({0, 0, 20, 10}, 2);
  ASSERT_EQ(halves.size(), 1u);
  EXPECT_NEAR(halves[0], 10, 1e-6);
  const std::vector<double> spread = cloud_at_column_10().spread().cuts_x({0, 0, 20, 10}, 2);
  EXPECT_NEAR(spread[0], 10 + 50.0 / 35, 1e-9);
}

TEST(CostEstimate, CutsThroughACloudWhenEveryPartNeedsIt) {
  // Three parts of a cloud as wide as the band: each pays for all of it, and the pixels are
  // cut in thirds.
  const CostEstimate e({{{0, 0, 30, 10}, 1}}, {{{0, 0, 30, 10}, 60}}, 1);
  const std::vector<double> thirds = e.cuts_x({0, 0, 30, 10}, 3);
  ASSERT_EQ(thirds.size(), 2u);
  EXPECT_NEAR(thirds[0], 10, 1e-6);
  EXPECT_NEAR(thirds[1], 20, 1e-6);
}

TEST(CostEstimate, SpreadKeepsTheTotalOnTheFootprintsPixels) {
  const CostEstimate s = cloud_at_column_10().spread();
  EXPECT_DOUBLE_EQ(s.total(), 300);
  EXPECT_DOUBLE_EQ(s.cost({10, 0, 1, 10}), 10 + 25);
  EXPECT_DOUBLE_EQ(s.per_triangle(), 0);
}

TEST(FitPerTriangle, FindsThePriceOfExactTimes) {
  // seconds = 0.5 ms + 2 ns a pixel + 30 ns a triangle touched.
  std::vector<TileSample> tiles;
  const double pixels[] = {1e4, 5e4, 2e4, 8e4, 3e4}, triangles[] = {0, 4e4, 9e4, 1e4, 2e4};
  for (int i = 0; i < 5; ++i)
    tiles.push_back({5e-4 + 2e-9 * pixels[i] + 3e-8 * triangles[i], pixels[i], triangles[i]});
  EXPECT_NEAR(fit_per_triangle(tiles), 3e-8, 1e-12);
}

TEST(FitPerTriangle, NeverLeavesATileLessThanNothingForItsPixels) {
  // The tiles say 1 per triangle, but one tile took only 0.2 per triangle it touched.
  std::vector<TileSample> tiles{{10, 1, 10}, {20, 1, 20}, {30, 2, 30}, {40, 1, 40}, {2, 1, 10}};
  EXPECT_DOUBLE_EQ(fit_per_triangle(tiles), 0.2);
}

TEST(FitPerTriangle, NothingToFitIsZero) {
  EXPECT_EQ(fit_per_triangle({}), 0);
  EXPECT_EQ(fit_per_triangle({{1, 10, 5}, {2, 20, 10}, {3, 30, 20}}), 0);  // too few tiles
  EXPECT_EQ(fit_per_triangle({{1, 10, 0}, {2, 20, 0}, {3, 30, 0}, {4, 5, 0}}), 0);
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

Wall four_tile_wall() {
  Wall w = two_tile_wall();
  w.tiling.rects = {{0, 0, 25, 50}, {25, 0, 25, 50}, {50, 0, 30, 50}, {80, 0, 20, 50}};
  return w;
}

TEST(CostEstimate, FromLayoutPricesTheFootprintsAndStillGivesEveryTileItsTime) {
  const TileLayout layout = plan_layout(four_tile_wall());
  // A batch of 1000 triangles across the middle two tiles, one of 500 in the last; each tile
  // took 1 ms + 1 us a pixel + 2 us a triangle it drew.
  const Footprints batches{{{20, 10, 40, 10}, 1000}, {{85, 0, 5, 5}, 500}};
  const auto time_of = [&](const Rect& r) {
    double drawn = 0;
    for (const BatchFootprint& f : batches)
      drawn += intersect(f.on_canvas, r).empty() ? 0 : f.triangles;
    return 1e-3 + 1e-6 * double(r.area()) + 2e-6 * drawn;
  };
  TileSeconds seconds(2);
  for (std::size_t s = 0; s < 2; ++s) {
    for (const PackedTile& t : layout.pipeservers[s].tiles)
      seconds[s].push_back(time_of(t.tile.on_canvas));
  }
  const CostEstimate e = CostEstimate::from_layout(layout, seconds, batches);
  EXPECT_NEAR(e.per_triangle(), 2e-6, 1e-12);
  for (std::size_t s = 0; s < 2; ++s) {
    for (std::size_t i = 0; i < seconds[s].size(); ++i)
      EXPECT_NEAR(e.cost(layout.pipeservers[s].tiles[i].tile.on_canvas), seconds[s][i], 1e-12);
  }
  // A one-column tile through the first batch pays all of its triangles.
  EXPECT_GT(e.cost({30, 0, 1, 50}), 2e-3);
  // Without footprints, the same times are spread over the pixels alone.
  EXPECT_EQ(CostEstimate::from_layout(layout, seconds).per_triangle(), 0);
}

TEST(CostEstimate, ABatchAcrossAMullionIsPaidOnEachDisplay) {
  Wall w = four_tile_wall();
  Display left = w.displays[0], right = w.displays[0];
  left.width = right.width = 50;
  right.canvas_x = 50;
  w.displays = {left, right};
  const TileLayout layout = plan_layout(w);
  // Seconds = 1 ms + 1 us a pixel + 2 us a triangle drawn; the batch reaches tiles 0, 1 and 2.
  const Footprints batch{{{20, 10, 40, 10}, 1000}};
  TileSeconds seconds(2);
  for (std::size_t s = 0; s < 2; ++s) {
    for (const PackedTile& t : layout.pipeservers[s].tiles) {
      const Rect& r = t.tile.on_canvas;
      const bool drawn = !intersect(batch[0].on_canvas, r).empty();
      seconds[s].push_back(1e-3 + 1e-6 * double(r.area()) + (drawn ? 2e-3 : 0));
    }
  }
  const CostEstimate e = CostEstimate::from_layout(layout, seconds, batch);
  EXPECT_NEAR(e.per_triangle(), 2e-6, 1e-12);
  // Ten columns across the mullion are two display tiles, each drawing the whole batch.
  EXPECT_NEAR(e.cost({45, 0, 10, 50}), e.cost({45, 0, 5, 50}) + e.cost({50, 0, 5, 50}), 1e-12);
  EXPECT_GT(e.cost({50, 0, 5, 50}), 2e-3);
}

TEST(CostEstimate, FromLayoutRefusesTimesOfAnotherShape) {
  const TileLayout layout = plan_layout(two_tile_wall());
  EXPECT_THROW(CostEstimate::from_layout(layout, {{1.0}}), std::invalid_argument);
  EXPECT_THROW(CostEstimate::from_layout(layout, {{1.0}, {1.0, 2.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace l2
