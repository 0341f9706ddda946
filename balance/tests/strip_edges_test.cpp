#include "balance/strip_edges.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

// A 100x100 canvas whose top-left quarter costs 3 per pixel and the rest 1: 15000 in all,
// 10000 of it in the top half.
CostEstimate heavy_top_left() {
  return CostEstimate({{{0, 0, 50, 50}, 3}, {{50, 0, 50, 50}, 1}, {{0, 50, 100, 50}, 1}});
}

TEST(StripEdges, StartEven) {
  const StripEdges s(100, 100, 2, 2);
  EXPECT_EQ(s.tiles(), (std::vector<Rect>{
                           {0, 0, 50, 50}, {50, 0, 50, 50}, {0, 50, 50, 50}, {50, 50, 50, 50}}));
}

TEST(StripEdges, WithFullGainTheEdgesJumpToBalance) {
  StripEdges s(100, 100, 2, 2);
  s.step(heavy_top_left(), {1.0, 0});
  // Rows: 200 per row above 50, half of 15000 at 7500 / 200.
  EXPECT_DOUBLE_EQ(s.rows()[1], 37.5);
  // Strip 0 is rows 0..38 (37.5 rounded): 114 per column on the left, half of 7600 at
  // 3800 / 114.
  EXPECT_DOUBLE_EQ(s.columns(0)[1], 3800.0 / 114);
  // Strip 1 is rows 38..100: 12 rows of the top patches and 50 of the bottom one: 86 per
  // column on the left (36 + 50), 62 on the right; half of 7400 at 3700 / 86.
  EXPECT_DOUBLE_EQ(s.columns(1)[1], 3700.0 / 86);
  EXPECT_EQ(s.tiles(), (std::vector<Rect>{
                           {0, 0, 33, 38}, {33, 0, 67, 38}, {0, 38, 43, 62}, {43, 38, 57, 62}}));
}

TEST(StripEdges, HalfGainMovesHalfWay) {
  StripEdges s(100, 100, 2, 2);
  s.step(heavy_top_left(), {0.5, 0});
  EXPECT_DOUBLE_EQ(s.rows()[1], 50 + 0.5 * (37.5 - 50));
}

TEST(StripEdges, AStripWithNothingMeasuredKeepsItsSubStrips) {
  // The strip edge's target (row 25) lies within the dead band, so strip 1 stays rows 50..100,
  // where nothing was measured: its sub-strip edge has no target to move to.
  StripEdges s(100, 100, 2, 2);
  s.step(CostEstimate({{{0, 0, 100, 50}, 1}, {{0, 50, 100, 50}, 0}}), {1.0, 30});
  EXPECT_DOUBLE_EQ(s.rows()[1], 50);
  EXPECT_DOUBLE_EQ(s.columns(1)[1], 50);
}

TEST(StripEdges, ASubStripEdgeStopsAtACloudRatherThanCutThroughIt) {
  // 1 per pixel over 20x10, and ten batches of 10 triangles at columns 10..13, 1 a triangle in
  // every tile a footprint touches. A cut through the cloud (10 < x < 14) makes both tiles pay
  // its 100; at its left edge the right tile pays 200 and the left 100, the least largest part.
  // Spread over its pixels instead, the cloud would put the edge at 11.43, through it.
  const CostEstimate cloud({{{0, 0, 20, 10}, 1}}, Footprints(10, {{10, 0, 4, 10}, 10}), 1);
  StripEdges s(20, 10, 1, 2);
  s.step(cloud, {1.0, 0});
  EXPECT_NEAR(s.columns(0)[1], 10, 1e-6);
  EXPECT_EQ(s.tiles(), (std::vector<Rect>{{0, 0, 10, 10}, {10, 0, 10, 10}}));
  StripEdges spread(20, 10, 1, 2);
  spread.step(cloud.spread(), {1.0, 0});
  EXPECT_EQ(spread.tiles(), (std::vector<Rect>{{0, 0, 11, 10}, {11, 0, 9, 10}}));
}

}  // namespace
}  // namespace l2
