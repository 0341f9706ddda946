#include "pipeserver/pipeserver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <ctime>
#include <stdexcept>

#include "image/turn.hpp"
#include "pipeserver/depth_out.hpp"
#include "pipeserver/gl_api.hpp"
#include "pipeserver/scan_out.hpp"
#include "pipeserver/tile_renderer.hpp"

namespace l2 {

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// CPU time of the whole process (OSMesa's rendering threads included), in ms: what a tile costs
// whatever else the machine runs at the same time.
double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
}

const PipeserverPlan& plan_of(const TileLayout& layout, int pipeserver) {
  if (pipeserver < 0 || pipeserver >= static_cast<int>(layout.pipeservers.size())) {
    throw std::out_of_range(fmt::format("pipeserver {} does not exist: the wall has {} (0..{})",
                                        pipeserver, layout.pipeservers.size(),
                                        static_cast<int>(layout.pipeservers.size()) - 1));
  }
  return layout.pipeservers[static_cast<std::size_t>(pipeserver)];
}

glm::vec3 key_colour(std::uint32_t key) {
  return glm::vec3(static_cast<float>(key >> 16 & 0xFF), static_cast<float>(key >> 8 & 0xFF),
                   static_cast<float>(key & 0xFF)) /
         255.0f;
}

// `part` written into `whole` with its top-left corner at (x, y); it fits.
void paste(const RgbImage& part, RgbImage& whole, int x, int y) {
  for (int row = 0; row < part.height(); ++row)
    std::copy_n(part.row(row).data(), part.stride(),
                whole.row(y + row).data() + static_cast<std::size_t>(x) * RgbImage::kChannels);
}

// The part of display `d` that holds `tile` (a planned tile lies in one: split_at_displays).
DisplayPart part_holding(const StereoSpec& stereo, const Display& d, const Rect& tile) {
  for (const DisplayPart& p : display_parts(stereo, d))
    if (intersect(p.on_canvas, tile) == tile) return p;
  throw std::out_of_range(
      fmt::format("display {}: a tile at {},{} spans its halves", d.id, tile.x, tile.y));
}

}  // namespace

Pipeserver::Pipeserver(const TileLayout& layout, int pipeserver, Renderer renderer)
    : plan_(plan_of(layout, pipeserver)),
      canvas_(canvas_of(layout.wall)),
      stereo_(layout.wall.stereo),
      renderer_(renderer),
      headers_{FrameHeaders(plan_, false), FrameHeaders(plan_, true)},
      depth_skip_(depth_skip_of(layout, pipeserver, kMeshBackground)),
      frame_(plan_.fb_width, plan_.fb_height) {
  make_windows(layout.wall);
}

void Pipeserver::set_layout(const TileLayout& layout) {
  const PipeserverPlan& plan = plan_of(layout, plan_.pipeserver);
  if (plan.fb_width != plan_.fb_width || plan.fb_height != plan_.fb_height) {
    throw std::invalid_argument(fmt::format(
        "pipeserver {}: a new layout's framebuffer is {}x{}, this one's {}x{}", plan_.pipeserver,
        plan.fb_width, plan.fb_height, plan_.fb_width, plan_.fb_height));
  }
  plan_ = plan;
  canvas_ = canvas_of(layout.wall);
  stereo_ = layout.wall.stereo;
  headers_ = {FrameHeaders(plan_, false), FrameHeaders(plan_, true)};
  depth_skip_ = depth_skip_of(layout, plan_.pipeserver, kMeshBackground);
  make_windows(layout.wall);
}

void Pipeserver::make_windows(const Wall& wall) {
  // One GL context per size of a display's canvas rectangle: tiles of displays of one size share
  // it, one display at a time, each tile clearing its own rectangle. A new layout keeps the
  // contexts it can. A turned display is rendered upright, as the canvas is, and turned while its
  // tiles are packed (depth_out.hpp). A passive stereo wall's twins share a rectangle, not a
  // window: each eye's tiles are drawn with its own camera. A packed stereo display is two
  // windows, one a half, each showing its eye's picture of the whole display squeezed.
  windows_.clear();
  for (int i = 0; i < static_cast<int>(plan_.tiles.size()); ++i) {
    const DisplayTile& t = plan_.tiles[static_cast<std::size_t>(i)].tile;
    const Display& d = wall.displays.at(static_cast<std::size_t>(t.display));
    const DisplayPart part = part_holding(wall.stereo, d, t.on_canvas);
    const Rect& r = part.on_canvas;
    const auto at = std::find_if(contexts_.begin(), contexts_.end(), [&](const auto& c) {
      return c->width() == r.w && c->height() == r.h;
    });
    const std::size_t context = static_cast<std::size_t>(at - contexts_.begin());
    if (at == contexts_.end())
      contexts_.push_back(std::make_unique<GlContext>(r.w, r.h, renderer_));
    auto w = std::find_if(windows_.begin(), windows_.end(),
                          [&](const Window& x) { return x.on_canvas == r && x.eye == part.eye; });
    if (w == windows_.end()) {
      windows_.push_back({r, part.eye, part.seen, context, {}});
      w = windows_.end() - 1;
    }
    w->tiles.push_back(i);
  }
  std::stable_sort(windows_.begin(), windows_.end(), [](const Window& a, const Window& b) {
    return std::pair(a.context, a.eye) < std::pair(b.context, b.eye);
  });
}

RgbImage& Pipeserver::render_frame(int frame, Scene& scene,
                                   const std::function<void(std::span<std::uint8_t>)>& dense) {
  render_frame(frame, scene, frame_.bytes(), dense);
  return frame_;
}

std::span<std::uint8_t> Pipeserver::render_frame(
    int frame, Scene& scene, std::span<std::uint8_t> dst,
    const std::function<void(std::span<std::uint8_t>)>& dense) {
  // A short buffer is refused before the render.
  const std::size_t bytes =
      static_cast<std::size_t>(plan_.fb_width) * static_cast<std::size_t>(plan_.fb_height) * 3;
  if (dst.size() < bytes) {
    throw std::invalid_argument(
        fmt::format("pipeserver {}: frame buffer of {} bytes, a {}x{} frame needs {}",
                    plan_.pipeserver, dst.size(), plan_.fb_width, plan_.fb_height, bytes));
  }
  // An active stereo wall's frame is one eye of an application frame; headers and stamp still
  // follow the frame itself.
  const FrameEye shows = frame_eye(stereo_, frame);
  scene.set_frame(shows.frame);
  // Every pixel is written: black first, then the tiles, then the headers over the gaps.
  std::memset(dst.data(), 0, bytes);
  times_ = {};
  times_.tile_ms.assign(plan_.tiles.size(), 0.0);
  render_windows(scene, dst, shows.eye);
  const auto t0 = Clock::now();
  const FrameHeaders& headers = headers_[frame_parity(frame) ? 1 : 0];
  const std::size_t row_bytes = static_cast<std::size_t>(plan_.fb_width) * 3;
  for (int y = 0; y < plan_.fb_height; ++y) {
    headers.draw_row(y, dst.subspan(static_cast<std::size_t>(y) * row_bytes, row_bytes));
  }
  times_.scanout_ms += ms_since(t0);
  if (dense) dense(dst.first(bytes));
  if (sparse_depth_) {
    const auto t1 = Clock::now();
    sparse_depth_rows(plan_, frame_parity(frame), depth_skip_, dst, sparse_);
    times_.scanout_ms += ms_since(t1);
  }
  return dst.first(bytes);
}

void Pipeserver::render_windows(Scene& scene, std::span<std::uint8_t> dst, Eye frame_eye) {
  // Layer 0 sends its clear nearer than the far plane (depth_out.hpp).
  const std::uint32_t far_as = plan_.layer == 0 ? kFarDepth - 1 : kFarDepth;
  std::unique_ptr<TileRenderer> renderer;
  std::size_t context = contexts_.size();
  Eye eye = Eye::None;
  std::vector<Rect> regions;
  for (const Window& w : windows_) {
    auto t0 = Clock::now();
    const Eye window_eye = w.eye == Eye::None ? frame_eye : w.eye;
    if (w.context != context || window_eye != eye) {
      if (w.context != context) contexts_[w.context]->make_current();
      context = w.context;
      eye = window_eye;
      renderer = std::make_unique<TileRenderer>(
          scene, canvas_, GeometryShare{plan_.layer, plan_.layers}, StereoEye{eye, stereo_});
    }
    for (int i : w.tiles) {
      const DisplayTile& t = plan_.tiles[static_cast<std::size_t>(i)].tile;
      const double tile_start = cpu_ms();
      // A KEY tile is cleared to its key colour: what it does not draw is transparent (§7).
      renderer->draw_tile(
          t.on_canvas, w.on_canvas,
          t.compositing == Compositing::Key ? key_colour(t.key) : scene.clear_colour(), w.seen);
      // OSMesa has no timer queries: the tile's time is the CPU's until its pixels are done.
      gl().Finish();
      times_.tile_ms[static_cast<std::size_t>(i)] = cpu_ms() - tile_start;
    }
    // The window's tiles into its buffer: EGL's read back, OSMesa's there already.
    regions.clear();
    for (int i : w.tiles) {
      const Rect& c = plan_.tiles[static_cast<std::size_t>(i)].tile.on_canvas;
      regions.push_back({c.x - w.on_canvas.x, w.on_canvas.bottom() - c.bottom(), c.w, c.h});
    }
    contexts_[context]->finish(regions);
    times_.render_ms += ms_since(t0);
    t0 = Clock::now();
    for (int i : w.tiles) {
      const PackedTile& p = plan_.tiles[static_cast<std::size_t>(i)];
      const TileInWindow from{*contexts_[context], p.tile.on_canvas.x - w.on_canvas.x,
                              p.tile.on_canvas.y - w.on_canvas.y};
      copy_tile_out(p, from, far_as, dst, plan_.fb_width);
    }
    times_.scanout_ms += ms_since(t0);
  }
  if (renderer) {
    times_.buckets = renderer->stats();
    times_.footprints = renderer->footprints();
  }
}

RgbImage render_canvas_rect(const Canvas& canvas, const Rect& rect, Scene& scene, int frame,
                            const StereoEye& eye, const Rect& seen) {
  GlContext context(rect.w, rect.h);
  scene.set_frame(frame);
  TileRenderer renderer(scene, canvas, {}, eye);
  renderer.draw_tile(rect, rect, scene.clear_colour(), seen.empty() ? rect : seen);
  context.finish();
  RgbImage image(rect.w, rect.h);
  scan_out(context.rgba(), rect.w, rect.h, image.bytes());
  return image;
}

RgbImage render_reference(const TileLayout& layout, int display, Scene& scene, int frame) {
  const auto& displays = layout.wall.displays;
  if (display < 0 || display >= static_cast<int>(displays.size())) {
    throw std::out_of_range(
        fmt::format("display {} does not exist: the wall has {}", display, displays.size()));
  }
  const Display& d = displays[static_cast<std::size_t>(display)];
  const FrameEye shows = frame_eye(layout.wall.stereo, frame);
  const std::vector<DisplayPart> parts = display_parts(layout.wall.stereo, d);
  const auto render = [&](const DisplayPart& p) {
    return render_canvas_rect(canvas_of(layout.wall), p.on_canvas, scene, shows.frame,
                              {p.eye == Eye::None ? shows.eye : p.eye, layout.wall.stereo}, p.seen);
  };
  if (parts.size() == 1) return to_panel(render(parts.front()), d.orientation);
  // A packed display's halves, each its own render, side by side or one above the other (the
  // wall file refuses a turned one).
  RgbImage whole(d.width, d.height);
  for (const DisplayPart& p : parts)
    paste(render(p), whole, p.on_canvas.x - d.canvas_x, p.on_canvas.y - d.canvas_y);
  return whole;
}

}  // namespace l2
