// A batch of a scene as sort-first bucketing sees it: the canvas rectangle it may cover and
// the triangles drawn for it. Every tile the rectangle touches draws all of them again (the
// renderer transforms, clips and bins a batch's vertices once per tile; the scissor only
// saves pixels), so a tile costs its pixels plus the triangles of the footprints it touches.
#pragma once

#include <vector>

#include "tilelayout/geometry.hpp"

namespace l2 {

struct BatchFootprint {
  Rect on_canvas;
  double triangles = 0;

  bool operator==(const BatchFootprint&) const = default;
};

using Footprints = std::vector<BatchFootprint>;

}  // namespace l2
