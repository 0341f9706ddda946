// Draws a scene into tiles of the current GL context, sort-first: same camera for every tile,
// and each tile drawn exactly as the window of its display draws it — the display's
// translate/scale prepended to the projection, the display's viewport — scissored to the tile,
// with only the batches whose footprint overlaps the tile. So every tile's pixels are the
// display-sized render's pixels bit for bit: llvmpipe's rounding depends on window
// coordinates, and even an integer shift of the viewport changes a few colours by a level.
#pragma once

#include <memory>
#include <vector>

#include "image/rgb_image.hpp"
#include "pipeserver/bucketing.hpp"
#include "pipeserver/camera.hpp"
#include "pipeserver/scene.hpp"
#include "tilelayout/batch_footprint.hpp"
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
  // Prepares one frame: a clear of the whole framebuffer to black (colour and depth), every
  // batch's canvas footprint, and a renderer for each window of a session (Scene::windows, each
  // on a canvas of the window's size). The scene must already be at the frame to draw. Throws
  // std::invalid_argument for a session shared by depth layers. A stereo wall's tiles of one
  // eye are drawn by a renderer of that eye (camera.hpp's eye_camera).
  TileRenderer(const Scene& scene, const Canvas& canvas, GeometryShare share = {},
               const StereoEye& eye = {});

  // Draws canvas rectangle `on_canvas` as the window showing canvas rectangle `window` — the
  // current framebuffer, window.w x window.h, its row 0 the window's bottom row — draws it:
  // only the part inside `on_canvas`, first cleared to `clear` (0..1 per channel; the scene's
  // clear colour by default) and the far depth; then a session's windows over it, clipped to
  // the tile, back to front. `seen`: the canvas rectangle whose picture the window shows, when
  // it is not `window` itself: a packed stereo display's half shows the whole display squeezed
  // into it (tilelayout/wall.hpp's display_parts), only scenes of geometry (no pixels, no
  // windows: those are drawn at canvas pixels; std::invalid_argument).
  void draw_tile(const Rect& on_canvas, const Rect& window);
  void draw_tile(const Rect& on_canvas, const Rect& window, glm::vec3 clear);
  void draw_tile(const Rect& on_canvas, const Rect& window, glm::vec3 clear, const Rect& seen);

  // The windows' draws included.
  BucketStats stats() const;
  // Every batch with something of this share to draw: its footprint and the share's triangles
  // of it (a session's windows left out: their canvases are their own).
  Footprints footprints() const;

 private:
  struct Window {
    Rect on_canvas;
    std::unique_ptr<TileRenderer> renderer;
  };
  // `clear`: the whole framebuffer, once a frame (not again for each window).
  TileRenderer(const Scene& scene, const Canvas& canvas, GeometryShare share, const StereoEye& eye,
               bool clear);
  void make_windows(GeometryShare share, const StereoEye& eye);
  void draw_windows(const Rect& on_canvas, const Rect& window);
  // Draws primitives [first, first + count) of `batch`, with its texture when it has one.
  void draw_batch(const Batch& batch, std::size_t first, std::size_t count) const;
  void draw_primitives(const Batch& batch, std::size_t first, std::size_t count) const;

  const Scene& scene_;
  Canvas canvas_;
  Camera camera_;
  std::vector<Rect> footprints_;
  std::vector<bool> drawn_;
  // Per batch, the primitives of this share: [share_first_[i], + share_count_[i]).
  std::vector<std::size_t> share_first_, share_count_;
  BucketStats stats_;
  RgbImage pixels_;  // a picture or movie scene's tile
  std::vector<Window> windows_;
};

}  // namespace l2
