#include "balance/kd_cost_grid.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

// Two 40x50 displays with a 20-pixel mullion between them on a 100x50 canvas.
Wall mullion_wall() {
  Wall w;
  Display a, b;
  a.width = b.width = 40;
  a.height = b.height = 50;
  b.id = 1;
  b.canvas_x = 60;
  w.displays = {a, b};
  w.canvas_width = 100;
  w.canvas_height = 50;
  return w;
}

CostEstimate left_twice_right() {
  return CostEstimate({{{0, 0, 40, 50}, 2}, {{60, 0, 40, 50}, 1}});
}

TEST(KdCostGrid, CellsHoldCostPerVisiblePixel) {
  // Cell 0 is columns 0..50: 4000 over the 2000 pixels display 0 shows of it.
  EXPECT_EQ(kd_cost_grid(mullion_wall(), left_twice_right(), 2, 1),
            (std::vector<std::vector<double>>{{2.0, 1.0}}));
}

TEST(KdCostGrid, ACellNoDisplayShowsCostsNothing) {
  EXPECT_EQ(kd_cost_grid(mullion_wall(), left_twice_right(), 5, 1),
            (std::vector<std::vector<double>>{{2, 2, 0, 1, 1}}));
}

TEST(KdCostGrid, BlendMovesEachCellByTheGain) {
  EXPECT_EQ(blend_grids({{0, 4}}, {{2, 2}}, 0.5), (std::vector<std::vector<double>>{{1, 3}}));
  EXPECT_EQ(blend_grids({}, {{2, 2}}, 0.5), (std::vector<std::vector<double>>{{2, 2}}));
  EXPECT_EQ(blend_grids({{1}}, {{2, 2}}, 0.5), (std::vector<std::vector<double>>{{2, 2}}));
}

}  // namespace
}  // namespace l2
