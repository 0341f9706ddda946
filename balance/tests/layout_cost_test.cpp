#include "balance/layout_cost.hpp"

#include <gtest/gtest.h>

#include "test_walls.hpp"
#include "tilelayout/planner.hpp"

namespace l2 {
namespace {

// strips_wall: four 50x50 tiles; pipeserver 0 renders tiles 0 and 2, pipeserver 1 tiles 1, 3.
const TileSeconds kTimes = {{7.5, 2.5}, {2.5, 2.5}};

TEST(LayoutCost, TheMeasuredLayoutPredictsItsOwnFrame) {
  const TileLayout layout = plan_layout(test::strips_wall());
  const double overhead = tile_overhead(kTimes, 0.2);
  EXPECT_DOUBLE_EQ(overhead, 0.2 * 15 / 4);
  const CostEstimate pixels = pixel_estimate(layout, kTimes, overhead);
  EXPECT_DOUBLE_EQ(pixels.total(), 15 - 4 * overhead);
  EXPECT_DOUBLE_EQ(predict_frame(layout, pixels, overhead).slowest, 10);
  EXPECT_DOUBLE_EQ(predict_frame(layout, CostEstimate::from_layout(layout, kTimes), 0).slowest, 10);
}

TEST(LayoutCost, MoreTilesCostTheirOverheadEach) {
  const TileLayout four = plan_layout(test::strips_wall());
  Wall wall = test::strips_wall();
  wall.tiling.substrip_count = 4;  // eight 25x50 tiles, four a pipeserver
  const TileLayout eight = plan_layout(wall);
  const TileSeconds even = {{2.5, 2.5}, {2.5, 2.5}};
  const double overhead = tile_overhead(even, 0.2);  // 0.5 of each tile's 2.5
  const CostEstimate pixels = pixel_estimate(four, even, overhead);
  // The same pixels in twice the tiles: 8 + 4 x 0.5 a pipeserver, not the 5 they cost now.
  EXPECT_DOUBLE_EQ(predict_frame(eight, pixels, overhead).slowest, 6);
  // The uniform estimate alone sees no difference.
  EXPECT_DOUBLE_EQ(predict_frame(eight, CostEstimate::from_layout(four, even), 0).slowest, 5);
  // The work, both pipeservers summed: 10 on the measured tiles, 12 on twice as many.
  EXPECT_DOUBLE_EQ(predict_frame(four, pixels, overhead).work, 10);
  EXPECT_DOUBLE_EQ(predict_frame(eight, pixels, overhead).work, 12);
}

}  // namespace
}  // namespace l2
