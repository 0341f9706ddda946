// The seed paper's tiling: horizontal strips, each cut into vertical sub-strips. Every frame
// the strip edges move toward the rows that give every strip the same estimated cost, then
// the sub-strip edges of each (new) strip toward equal cost within it.
#pragma once

#include <vector>

#include "balance/cost_estimate.hpp"
#include "balance/edge_motion.hpp"
#include "tilelayout/geometry.hpp"

namespace l2 {

class StripEdges {
 public:
  // Evenly spaced, as `kind = "strips"` cuts a canvas (tilelayout's strip tiling).
  StripEdges(int canvas_width, int canvas_height, int strips, int substrips);

  // One frame of motion toward balance under `estimate`.
  void step(const CostEstimate& estimate, const EdgeMotion& motion);
  // The tiles at whole pixels, row-major (strip by strip, left to right), every tile at least
  // one pixel wide and tall.
  std::vector<Rect> tiles() const;

  const std::vector<double>& rows() const { return rows_; }
  const std::vector<double>& columns(int strip) const { return columns_[strip]; }

 private:
  int width_, height_;
  std::vector<double> rows_;                  // strip edges, rows_[0] = 0 .. height
  std::vector<std::vector<double>> columns_;  // sub-strip edges of each strip, 0 .. width
};

}  // namespace l2
