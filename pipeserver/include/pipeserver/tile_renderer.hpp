// Draws a scene into tiles of the current GL context, sort-first: same camera for every tile,
// the tile's translate/scale prepended to the projection, viewport and scissor on the tile's
// place in the framebuffer, and only the batches whose footprint overlaps the tile.
#pragma once

#include <vector>

#include "pipeserver/bucketing.hpp"
#include "pipeserver/camera.hpp"
#include "pipeserver/scene.hpp"
#include "tilelayout/geometry.hpp"

namespace l2 {

// The part of a scene's geometry a pipeserver draws. A depth wall (spec §7) splits the scene in
// draw order: its primitives (triangles; strips of a strip batch) are numbered across the
// batches in order, and share `layer` of `layers` is the contiguous run
// [P·layer/layers, P·(layer+1)/layers). Drawn in that order, the layers composited by depth in
// ascending order give what one GL_LESS render of everything gives.
struct GeometryShare {
  int layer = 0, layers = 1;
};

class TileRenderer {
 public:
  // Prepares one frame: GL state, a clear of the whole framebuffer to the scene's clear colour
  // (colour and depth), and every batch's canvas footprint. The scene must already be at the frame
  // to draw.
  TileRenderer(const Scene& scene, const Canvas& canvas, GeometryShare share = {});

  // Draws the canvas rectangle `on_canvas` into the framebuffer rectangle whose lower-left
  // corner is (gl_x, gl_y) in GL window coordinates (rows bottom to top), first clearing it to
  // `clear` (0..1 per channel; the scene's clear colour by default) when that is not black.
  void draw_tile(const Rect& on_canvas, int gl_x, int gl_y);
  void draw_tile(const Rect& on_canvas, int gl_x, int gl_y, glm::vec3 clear);

  const BucketStats& stats() const { return stats_; }

 private:
  // Draws primitives [first, first + count) of `batch`.
  void draw_batch(const Batch& batch, std::size_t first, std::size_t count) const;

  const Scene& scene_;
  Canvas canvas_;
  Camera camera_;
  std::vector<Rect> footprints_;
  std::vector<bool> drawn_;
  // Per batch, the primitives of this share: [share_first_[i], + share_count_[i]).
  std::vector<std::size_t> share_first_, share_count_;
  BucketStats stats_;
};

}  // namespace l2
