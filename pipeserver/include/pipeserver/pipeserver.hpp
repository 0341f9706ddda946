// One render node of the wall (spec §1, §4): renders every tile assigned to it as the window of
// its display would (so its pixels are the display-sized render's), copies it to its packed
// place in a 24-bit RGB frame, and draws the strip headers into the gaps with the frame's parity.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "image/rgb_image.hpp"
#include "pipeserver/bucketing.hpp"
#include "pipeserver/camera.hpp"
#include "pipeserver/depth_out.hpp"
#include "pipeserver/gl_context.hpp"
#include "pipeserver/scene.hpp"
#include "tilelayout/batch_footprint.hpp"
#include "tilelayout/frame_headers.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

struct FrameTimes {
  // Clear, draw every tile, glFinish, and the pixels into the context's buffer (OSMesa copies
  // them there as it finishes, EGL's are read back).
  double render_ms = 0;
  double scanout_ms = 0;  // tiles RGBA bottom-up -> RGB top-down (and depth), headers, black
  BucketStats buckets;
  // Each tile's draw, glFinish included, by plan().tiles index, in CPU time of the process:
  // the load balancer's measure (balance/). It leaves out each display window's set-up.
  std::vector<double> tile_ms;
  // The scene's batches this frame (its share of them on a depth wall; a session's windows
  // left out): what the load balancer prices a tile's overlap with.
  Footprints footprints;
  double total_ms() const { return render_ms + scanout_ms; }
};

// The logical canvas of a wall.
inline Canvas canvas_of(const Wall& wall) {
  return {wall.canvas_width, wall.canvas_height};
}

// Spec §6.1: frame k carries parity k mod 2.
inline bool frame_parity(int frame) {
  return (frame & 1) != 0;
}

// The mesh's background (spec §5: black unless configured), which `l2wall run` keeps: a layer-0
// pipeserver leaves its clear out where it is this colour (tilelayout/sparse_depth.hpp).
inline constexpr std::array<std::uint8_t, 3> kMeshBackground{0, 0, 0};

class Pipeserver {
 public:
  // Throws std::out_of_range when `pipeserver` is not a pipeserver of the layout. Its GL
  // contexts render with `renderer` (gl_context.hpp; by default the process's, --renderer's).
  Pipeserver(const TileLayout& layout, int pipeserver, Renderer renderer = process_renderer());

  // Sets the scene to `frame` (an active stereo wall's eye frame: its application frame, with
  // that eye's camera; tilelayout/wall.hpp's frame_eye), renders, draws the headers and scans out.
  // The returned frame stays valid until the next call, and the caller may mark it (a frame number
  // stamped in) instead of copying 1.4 MB a frame to do so.
  RgbImage& render_frame(int frame, Scene& scene,
                         const std::function<void(std::span<std::uint8_t>)>& dense = {});

  // The same, scanned out into `dst`: fb_width x fb_height RGB, rows of fb_width * 3 bytes, row
  // 0 on top, every pixel written (the live pipeserver passes its DVI link's back frame, so the
  // frame is not copied there afterwards). Returns the frame's bytes at the start of `dst`. Throws
  // std::invalid_argument when `dst` is smaller than a frame.
  // `dense`, when given, sees the frame before its DEPTH rows are made sparse: every tile whole
  // at its packed place, as the vizserver path's tile sender reads them.
  std::span<std::uint8_t> render_frame(
      int frame, Scene& scene, std::span<std::uint8_t> dst,
      const std::function<void(std::span<std::uint8_t>)>& dense = {});
  // Whether DEPTH rows go out sparse (tilelayout/sparse_depth.hpp), as they do unless turned
  // off: a dense frame routes to the same displays, which the tests compare.
  void set_sparse_depth(bool on) { sparse_depth_ = on; }

  // The same pipeserver in another layout of its wall (the load balancer's next frame): its
  // plan, headers and windows anew, its GL contexts kept. Throws std::out_of_range as the
  // constructor does, std::invalid_argument when the framebuffer size differs (the DVI link's).
  void set_layout(const TileLayout& layout);

  const PipeserverPlan& plan() const { return plan_; }
  const FrameTimes& last_times() const { return times_; }
  Renderer renderer() const { return renderer_; }

 private:
  // The tiles of one display (or one half of a packed stereo display: tilelayout/wall.hpp's
  // display_parts), rendered in a window of its size.
  struct Window {
    Rect on_canvas;           // the display or its half
    Eye eye = Eye::None;      // the display's on a passive stereo wall, the half's on a packed one
    Rect seen;                // the canvas rectangle it shows (squeezed on a packed wall)
    std::size_t context = 0;  // into contexts_
    std::vector<int> tiles;   // into plan_.tiles
  };
  // `frame_eye`: the eye of an active wall's frame, for windows of displays without one.
  void render_windows(Scene& scene, std::span<std::uint8_t> dst, Eye frame_eye);
  void make_windows(const Wall& wall);

  PipeserverPlan plan_;
  Canvas canvas_;
  StereoSpec stereo_;
  Renderer renderer_;
  std::vector<std::unique_ptr<GlContext>> contexts_;  // one per display size
  std::vector<Window> windows_;                       // by context, then display
  std::array<FrameHeaders, 2> headers_;               // encoded once, by frame parity
  DepthSkip depth_skip_;  // what this pipeserver's DEPTH rows may leave out, by the layout
  bool sparse_depth_ = true;
  SparseScratch sparse_;
  RgbImage frame_;
  FrameTimes times_;
};

// What display `display` should show for `frame`: the display's canvas rectangle rendered
// whole, at display resolution, with the same camera (its eye's on a passive stereo wall, the
// frame's on an active one, whose frames are eye frames: tilelayout/wall.hpp's frame_eye; its own
// GL context), turned into the panel's raster as it hangs (image/orientation.hpp). On a packed
// stereo wall each half is rendered alone, its eye's picture of the whole display squeezed.
RgbImage render_reference(const TileLayout& layout, int display, Scene& scene, int frame);

// Any canvas rectangle rendered alone into an image of its size (its own GL context): the
// reference render's engine, and the whole-canvas render the tile tests crop. `seen`: the
// canvas rectangle whose picture fills the image, squeezed when it is larger (a packed stereo
// half); empty: `rect` itself.
RgbImage render_canvas_rect(const Canvas& canvas, const Rect& rect, Scene& scene, int frame,
                            const StereoEye& eye = {}, const Rect& seen = {});

}  // namespace l2
