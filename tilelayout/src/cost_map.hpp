// The work of rendering a canvas rectangle, for the k-d split. Private to the planner.
//
// The cost grid is stretched over the canvas; pixels no display shows cost nothing, since
// nobody renders them. The density is then constant on the cells cut by grid lines and display
// edges, so the integral F(x, y) over [0,x) x [0,y) is bilinear within a cell: a summed-area
// table over the cell corners answers any rectangle exactly, whatever the canvas size.
#pragma once

#include <vector>

#include "tilelayout/wall.hpp"

namespace l2 {

class CostMap {
 public:
  explicit CostMap(const Wall& wall);
  double cost(const Rect& r) const;

 private:
  double integral(int x, int y) const;  // F(x, y)
  std::vector<int> xs_, ys_;            // cell edges, sorted, first 0, last canvas size
  std::vector<double> sums_;            // F at (xs_[i], ys_[j]), row j, ys_.size() x xs_.size()
};

}  // namespace l2
