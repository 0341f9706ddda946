// Sort-first bucketing: a batch is drawn only into the tiles its screen footprint overlaps.
#pragma once

#include <glm/mat4x4.hpp>

#include "pipeserver/camera.hpp"
#include "pipeserver/scene.hpp"
#include "tilelayout/geometry.hpp"

namespace l2 {

// The canvas pixels a box (model space) may cover under `clip_from_model`, conservatively: the
// projected corners' bounds grown by one pixel for rasterisation rounding. A box reaching to or
// behind the eye plane gets the whole canvas, since its projection is unbounded.
Rect canvas_footprint(const Canvas& canvas, const glm::mat4& clip_from_model, const Box& box);

// Whether a batch with this footprint must be drawn into the tile showing canvas rect `tile`.
inline bool overlaps(const Rect& footprint, const Rect& tile) {
  return !intersect(footprint, tile).empty();
}

// How much sort-first costs: batches that touch any tile of a pipeserver and the number of
// (batch, tile) draws. WireGL's overlap factor is draws per batch.
struct BucketStats {
  long batches = 0;     // batches drawn into at least one tile
  long tile_draws = 0;  // sum over batches of the tiles each was drawn into
  double overlap_factor() const {
    return batches == 0 ? 0.0 : static_cast<double>(tile_draws) / static_cast<double>(batches);
  }
};

}  // namespace l2
