// Draws a scene into tiles of the current GL context, sort-first: same camera for every tile,
// the tile's translate/scale prepended to the projection, viewport and scissor on the tile's
// place in the framebuffer, and only the batches whose footprint overlaps the tile.
#pragma once

#include <vector>

#include "image/rgb_image.hpp"
#include "pipeserver/bucketing.hpp"
#include "pipeserver/camera.hpp"
#include "pipeserver/scene.hpp"
#include "tilelayout/geometry.hpp"

namespace l2 {

class TileRenderer {
 public:
  // Prepares one frame: GL state, a clear of the whole framebuffer to the scene's clear colour
  // (colour and depth), and every batch's canvas footprint. The scene must already be at the frame
  // to draw.
  TileRenderer(const Scene& scene, const Canvas& canvas);

  // Draws the canvas rectangle `on_canvas` into the framebuffer rectangle whose lower-left
  // corner is (gl_x, gl_y) in GL window coordinates (rows bottom to top), first clearing it to
  // the scene's clear colour when that is not black.
  void draw_tile(const Rect& on_canvas, int gl_x, int gl_y);

  const BucketStats& stats() const { return stats_; }

 private:
  void draw_batch(const Batch& batch) const;

  const Scene& scene_;
  Canvas canvas_;
  Camera camera_;
  std::vector<Rect> footprints_;
  std::vector<bool> drawn_;
  BucketStats stats_;
  RgbImage pixels_;  // a picture or movie scene's tile
};

}  // namespace l2
