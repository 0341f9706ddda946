// Header drawing plus scan-out must stay under 2% of frame time on the default wall (issue).
// Renders frames of every pipeserver of the default wall with the default bunny, and prints
// the share, with a memcpy of one framebuffer as the same-run baseline for the scan-out cost.
// The headers are drawn during the scan-out, row by row, so one time covers both.
// Frame time is what a wall frame lasts: the render + scan-out time, but never less
// than one refresh period of the wall (a frame is shown for at least one refresh). The share
// of the bare measured time is printed too: for the light default bunny it is the larger one.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "command_line/parse.hpp"
#include "dvi_link/frame_delta.hpp"
#include "pipeserver/gl_context.hpp"
#include "pipeserver/pipeserver.hpp"
#include "pipeserver/scan_out.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double memcpy_ms(std::size_t bytes) {
  std::vector<std::uint8_t> a(bytes, 1), b(bytes);
  std::vector<double> t;
  for (int i = 0; i < 30; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    std::memcpy(b.data(), a.data(), bytes);
    t.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    a[static_cast<std::size_t>(i)] = b[static_cast<std::size_t>(i) + 1];  // keep the copies alive
  }
  return median(t);
}

// What sending pipeserver 0's frames over a network costs it (dvi_link/frame_delta.hpp): each
// scanned-out frame encoded against the one before, per codec, timed against a memcpy of the
// frame in the same run, with the bytes it leaves and the link rate it keeps up with.
void frame_delta_figures(const l2::TileLayout& layout, l2::Scene& scene, int frames) {
  l2::Pipeserver ps(layout, 0);
  std::vector<std::vector<std::uint8_t>> scanned;
  for (int k = 0; k < frames; ++k) {
    const l2::RgbImage& f = ps.render_frame(k, scene);
    scanned.emplace_back(f.bytes().begin(), f.bytes().end());
  }
  const std::size_t bytes = scanned.front().size();
  const double base = memcpy_ms(bytes);
  std::printf(
      "frames to the network (pipeserver 0, each against the one before; memcpy of a "
      "frame %.3f ms):\n",
      base);
  for (const l2::LinkCodec codec : {l2::LinkCodec::Raw, l2::LinkCodec::Lz4, l2::LinkCodec::Zstd}) {
    const auto& plan = ps.plan();
    l2::FrameDeltaEncoder encoder(plan.fb_width, plan.fb_height, codec);
    std::vector<double> ms;
    double sent = 0;
    for (std::size_t k = 0; k < scanned.size(); ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      const std::size_t n = encoder.encode(scanned[k]).size();
      const double t =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      if (k == 0) continue;  // from black: the first frame is not what a run sends
      ms.push_back(t);
      sent += static_cast<double>(n);
    }
    const double mb_per_s = static_cast<double>(bytes) / median(ms) / 1e3;
    // Worth it on a link slower than the frames are encoded: the frame is encoded before it
    // would have crossed that link whole.
    std::printf(
        "  %-4s: encode %.3f ms (%.2fx a memcpy), %.1fx fewer bytes; encodes %.0f MB/s of "
        "frames, faster than a link of %.1f Gbit/s carries them whole\n",
        std::string(l2::link_codec_name(codec)).c_str(), median(ms), median(ms) / base,
        static_cast<double>(bytes) * static_cast<double>(ms.size()) / sent, mb_per_s,
        mb_per_s * 8 / 1e3);
  }
}

// Render time per renderer, side by side (--renderer, gl_context.hpp): every pipeserver of the
// wall renders the same frames with OSMesa and with EGL, a frame of one then the same frame of
// the other (which goes first alternates), so that a machine busy with other work slows both
// alike. Medians per pipeserver and the ratio EGL / OSMesa, OSMesa timed in the same run: about
// 1 where EGL is llvmpipe too (Mesa's software device), below 1 by what a GPU gains.
void renderer_figures(const l2::TileLayout& layout, l2::Scene& scene, int frames) {
  const l2::RendererDecision osmesa = l2::use_renderer(l2::RendererChoice::OsMesa);
  l2::RendererDecision egl;
  try {
    egl = l2::use_renderer(l2::RendererChoice::Egl);
  } catch (const l2::RendererError& e) {
    std::printf("render time per renderer: EGL cannot render here (%s); OSMesa alone\n", e.what());
    return;
  }
  std::printf(
      "render time per renderer (every pipeserver, the same frames alternately, medians of %d "
      "frames after the first):\n  osmesa: %s\n  egl:    %s\n",
      frames, osmesa.line().c_str(), egl.line().c_str());
  double sum_osmesa = 0, sum_egl = 0;
  for (int s = 0; s < static_cast<int>(layout.pipeservers.size()); ++s) {
    l2::Pipeserver by_osmesa(layout, s, l2::Renderer::OsMesa);
    l2::Pipeserver by_egl(layout, s, l2::Renderer::Egl);
    std::vector<double> o, e;
    for (int k = 0; k <= frames; ++k) {
      l2::Pipeserver& first = k % 2 == 0 ? by_osmesa : by_egl;
      l2::Pipeserver& second = k % 2 == 0 ? by_egl : by_osmesa;
      first.render_frame(k, scene);
      second.render_frame(k, scene);
      if (k == 0) continue;  // contexts made and llvmpipe's shaders compiled: not a frame's cost
      o.push_back(by_osmesa.last_times().render_ms);
      e.push_back(by_egl.last_times().render_ms);
    }
    std::printf("  pipeserver %d: osmesa %.2f ms, egl %.2f ms: egl / osmesa %.2f\n", s, median(o),
                median(e), median(e) / median(o));
    sum_osmesa += median(o);
    sum_egl += median(e);
  }
  std::printf(
      "  all pipeservers (sum of medians): osmesa %.2f ms, egl %.2f ms: egl / osmesa %.2f\n",
      sum_osmesa, sum_egl, sum_egl / sum_osmesa);
  l2::use_renderer(l2::RendererChoice::OsMesa);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "pipeserver_bench: renders frames on every pipeserver of the built-in default wall and\n"
      "prints, per pipeserver, the render time, the scan-out time (strip headers drawn in) "
      "against\n"
      "a memcpy of the framebuffer measured in the same run, and the share of the frame time the\n"
      "headers and scan-out take (target < 2%); then the render time per renderer, OSMesa and\n"
      "EGL side by side (--renderers: that alone). Exit status 0 when the worst share is under\n"
      "2% (or with --renderers), 1 when not, 2 on a usage error."};
  std::string scene_name = "mesh";
  int frames = 20;
  app.add_option("scene", scene_name, "scene to render")
      ->check(CLI::IsMember(l2::built_in_scene_names()))
      ->capture_default_str();
  app.add_option("frames", frames, "frames per pipeserver; figures are medians")
      ->check(CLI::Range(3, 100000))
      ->capture_default_str();
  bool renderers_only = false;
  app.add_flag("--renderers", renderers_only,
               "only the render time per renderer: OSMesa and EGL side by side, the ratio EGL / "
               "OSMesa (scripts/renderer-bench.sh runs it three times)");
  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;
  const l2::TileLayout layout = l2::plan_layout(l2::default_wall());
  auto scene = l2::make_scene(scene_name);
  std::printf("default wall '%s': canvas %dx%d, %zu displays, %zu pipeservers, framebuffer %dx%d\n",
              layout.wall.name.c_str(), layout.wall.canvas_width, layout.wall.canvas_height,
              layout.wall.displays.size(), layout.pipeservers.size(), layout.wall.framebuffer_width,
              layout.wall.framebuffer_height);
  std::printf("scene %s (%zu triangles), %d frames per pipeserver, medians:\n", scene_name.c_str(),
              scene->triangle_count(), frames);
  if (renderers_only) {
    renderer_figures(layout, *scene, frames);
    return 0;
  }
  const double period_ms = 1000.0 / layout.wall.refresh_hz;
  double worst_share = 0, worst_bare = 0;
  for (int s = 0; s < static_cast<int>(layout.pipeservers.size()); ++s) {
    l2::Pipeserver ps(layout, s);
    std::vector<double> render, scan, share, bare, overlap;
    for (int k = 0; k < frames; ++k) {
      ps.render_frame(k, *scene);
      const auto& t = ps.last_times();
      render.push_back(t.render_ms);
      scan.push_back(t.scanout_ms);
      share.push_back(100.0 * t.scanout_ms / std::max(t.total_ms(), period_ms));
      bare.push_back(100.0 * t.scanout_ms / t.total_ms());
      overlap.push_back(t.buckets.overlap_factor());
    }
    const auto& plan = ps.plan();
    const std::size_t rgba_bytes =
        static_cast<std::size_t>(plan.fb_width) * static_cast<std::size_t>(plan.fb_height) * 4;
    const double base = memcpy_ms(rgba_bytes);
    worst_share = std::max(worst_share, median(share));
    worst_bare = std::max(worst_bare, median(bare));
    std::printf(
        "  pipeserver %d: %zu tiles; render %.2f ms, scan-out with headers %.3f ms "
        "(%.2fx a memcpy of the RGBA framebuffer, %.3f ms); headers+scan-out %.2f%% of the frame "
        "time, %.2f%% of the bare render+scan-out; overlap %.2f\n",
        s, plan.tiles.size(), median(render), median(scan), median(scan) / base, base,
        median(share), median(bare), median(overlap));
  }
  std::printf(
      "worst headers+scan-out share of frame time (>= %.2f ms at %d Hz): %.2f%% (target < 2%%): "
      "%s; of the bare measured time: %.2f%%\n",
      period_ms, layout.wall.refresh_hz, worst_share, worst_share < 2.0 ? "PASS" : "FAIL",
      worst_bare);
  frame_delta_figures(layout, *scene, frames);
  renderer_figures(layout, *scene, frames);
  return worst_share < 2.0 ? 0 : 1;
}
