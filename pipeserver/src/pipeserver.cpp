#include "pipeserver/pipeserver.hpp"

#include <GL/gl.h>
#include <fmt/format.h>

#include <chrono>
#include <stdexcept>

#include "pipeserver/depth_out.hpp"
#include "pipeserver/scan_out.hpp"
#include "pipeserver/tile_renderer.hpp"

namespace l2 {

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

const ServerPlan& plan_of(const TileLayout& layout, int server) {
  if (server < 0 || server >= static_cast<int>(layout.servers.size())) {
    throw std::out_of_range(fmt::format("pipeserver {} does not exist: the wall has {} (0..{})",
                                        server, layout.servers.size(),
                                        static_cast<int>(layout.servers.size()) - 1));
  }
  return layout.servers[static_cast<std::size_t>(server)];
}

glm::vec3 key_colour(std::uint32_t key) {
  return glm::vec3(static_cast<float>(key >> 16 & 0xFF), static_cast<float>(key >> 8 & 0xFF),
                   static_cast<float>(key & 0xFF)) /
         255.0f;
}

}  // namespace

Pipeserver::Pipeserver(const TileLayout& layout, int server)
    : plan_(plan_of(layout, server)),
      canvas_(canvas_of(layout.wall)),
      gl_(plan_.fb_width, plan_.fb_height),
      headers_{FrameHeaders(plan_, false), FrameHeaders(plan_, true)},
      frame_(plan_.fb_width, plan_.fb_height) {}

RgbImage& Pipeserver::render_frame(int frame, Scene& scene) {
  render_frame(frame, scene, frame_.bytes());
  return frame_;
}

std::span<std::uint8_t> Pipeserver::render_frame(int frame, Scene& scene,
                                                 std::span<std::uint8_t> dst) {
  // Checked here although scan_out checks again: a short buffer is refused before the render.
  const std::size_t bytes =
      static_cast<std::size_t>(plan_.fb_width) * static_cast<std::size_t>(plan_.fb_height) * 3;
  if (dst.size() < bytes) {
    throw std::invalid_argument(
        fmt::format("pipeserver {}: frame buffer of {} bytes, a {}x{} frame needs {}", plan_.server,
                    dst.size(), plan_.fb_width, plan_.fb_height, bytes));
  }
  gl_.make_current();
  scene.set_frame(frame);

  auto t0 = Clock::now();
  TileRenderer renderer(scene, canvas_, {plan_.layer, plan_.layers});
  for (const PackedTile& p : plan_.tiles) {
    const Rect& r = p.tile.on_canvas;
    // Packed rows count from the top; GL windows from the bottom. A KEY tile is cleared to its
    // key colour, so what it does not draw is transparent (spec §7).
    const glm::vec3 clear =
        p.tile.compositing == Compositing::Key ? key_colour(p.tile.key) : scene.clear_colour();
    renderer.draw_tile(r, p.fb_x, plan_.fb_height - p.fb_y - r.h, clear);
  }
  glFinish();
  times_.render_ms = ms_since(t0);
  times_.buckets = renderer.stats();

  // Headers go in during scan-out, each scanline's right after it is converted: they are RGB
  // words, and the render left the gaps black (the scissor keeps tiles out of them).
  t0 = Clock::now();
  scan_out(gl_.rgba(), plan_.fb_width, plan_.fb_height, dst, headers_[frame_parity(frame) ? 1 : 0]);
  scan_out_depth(plan_, plan_.layer == 0 ? kFarDepth - 1 : kFarDepth, dst);
  times_.scanout_ms = ms_since(t0);
  return dst.first(bytes);
}

RgbImage render_canvas_rect(const Canvas& canvas, const Rect& rect, Scene& scene, int frame) {
  GlContext gl(rect.w, rect.h);
  scene.set_frame(frame);
  TileRenderer renderer(scene, canvas);
  renderer.draw_tile(rect, 0, 0);
  glFinish();
  RgbImage image(rect.w, rect.h);
  scan_out(gl.rgba(), rect.w, rect.h, image.bytes());
  return image;
}

RgbImage render_reference(const TileLayout& layout, int display, Scene& scene, int frame) {
  const auto& displays = layout.wall.displays;
  if (display < 0 || display >= static_cast<int>(displays.size())) {
    throw std::out_of_range(
        fmt::format("display {} does not exist: the wall has {}", display, displays.size()));
  }
  return render_canvas_rect(canvas_of(layout.wall),
                            displays[static_cast<std::size_t>(display)].on_canvas(), scene, frame);
}

}  // namespace l2
