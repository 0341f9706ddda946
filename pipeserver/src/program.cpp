// The pipeserver program: renders one pipeserver's frame of a wall (tiles at their packed places,
// strip headers in the gaps, scanned out to 24-bit RGB) and, on request, the reference render of
// every display of that frame; or, with --live, a pipeserver of `l2wall run`. `pipeserver` is this
// with the built-in scenes, a program of your own (renderer.hpp) this with your drawing.
#include "pipeserver/renderer.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>

#include "base/socket.hpp"
#include "command_line/options.hpp"
#include "command_line/parse.hpp"
#include "dvi_link/frame_delta.hpp"
#include "image/folders.hpp"
#include "image/png_io.hpp"
#include "live_mode.hpp"
#include "pipeserver/gl_context.hpp"
#include "pipeserver/live_exit.hpp"
#include "pipeserver/pipeserver.hpp"
#include "pipeserver/renderer_choice.hpp"
#include "pipeserver/scene_cli.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

#ifdef L2_HAVE_MPI
#include "mpi_link/mpi_control_channel.hpp"
#include "mpi_link/mpi_session.hpp"
#include "mpi_link/mpi_wire.hpp"
#include "mpi_link/rank_map.hpp"
#include "mpi_rank.hpp"
#endif

namespace {

struct Options {
  std::string wall;  // empty: the built-in default wall
  int pipeserver = 0;
  int frame = 0;
  int count = 1;
  std::string scene = "mesh";
  std::string out;
  std::string reference;
  l2::SceneOptions scene_options;
  l2::RendererChoice renderer = l2::RendererChoice::Auto;
};

void print_times(int pipeserver, int frame, const l2::FrameTimes& t) {
  const double share = 100.0 * t.scanout_ms / t.total_ms();
  std::printf(
      "pipeserver %d frame %d: render %.2f ms, scan-out with headers %.3f ms "
      "(%.2f%% of %.2f ms); batches %ld, tile draws %ld, overlap %.2f\n",
      pipeserver, frame, t.render_ms, t.scanout_ms, share, t.total_ms(), t.buckets.batches,
      t.buckets.tile_draws, t.buckets.overlap_factor());
}

int run(const Options& o) {
  const l2::Wall wall = o.wall.empty() ? l2::default_wall() : l2::load_wall(o.wall);
  const l2::TileLayout layout = l2::plan_layout(wall);
  for (const auto& w : layout.warnings)
    std::fprintf(stderr, "pipeserver: warning: %s\n", w.c_str());
  auto scene = l2::make_scene(o.scene, o.scene_options);
  // Here only: a live pipeserver leaves it to `l2wall run`, which says it once for the run.
  if (!scene->note().empty()) std::printf("%s\n", scene->note().c_str());
  // The folders before rendering: a folder that could not be made failed after the work.
  if (!o.out.empty()) l2::make_folders(o.out, "--out");
  if (!o.reference.empty()) l2::make_folders(o.reference, "--reference");
  // Decided before rendering (an EGL that cannot render is one line), said once something has
  // rendered (a file refused while rendering is one line too).
  const std::string renderer = l2::use_renderer(o.renderer).line();
  bool said = false;
  const auto say_renderer = [&] {
    if (!said) std::printf("pipeserver %d: renderer %s\n", o.pipeserver, renderer.c_str());
    said = true;
  };

  if (!o.out.empty()) {
    l2::Pipeserver ps(layout, o.pipeserver);
    const l2::RgbImage* frame = nullptr;
    for (int k = o.frame; k < o.frame + o.count; ++k) {
      frame = &ps.render_frame(k, *scene);
      say_renderer();
      print_times(o.pipeserver, k, ps.last_times());
    }
    // Named as `tilelayout --scanout` names its frames, so that both route the same way.
    const auto path = std::filesystem::path(o.out) / fmt::format("scanout-{}.png", o.pipeserver);
    l2::write_png(path, *frame);
    std::printf("wrote %s (%dx%d, %zu tiles)\n", path.c_str(), frame->width(), frame->height(),
                ps.plan().tiles.size());
  }
  if (!o.reference.empty()) {
    const int last = o.frame + o.count - 1;
    for (const auto& d : wall.displays) {
      const auto path = std::filesystem::path(o.reference) / fmt::format("display-{}.png", d.id);
      l2::write_png(path, l2::render_reference(layout, d.id, *scene, last));
      say_renderer();
      std::printf("wrote %s (reference, display %d, frame %d)\n", path.c_str(), d.id, last);
    }
  }
  return 0;
}

int run_live(const l2::LiveOptions& o) {
  try {
    return l2::run_live_mode(o);
  } catch (const l2::NetError& e) {
    std::fprintf(stderr, "pipeserver %d: %s\n", o.pipeserver, e.what());
    return l2::kExitLostCompositingServer;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pipeserver %d: %s\n", o.pipeserver, e.what());
    return 1;
  }
}

// A rank of an MPI run: a pipeserver that fails ends every rank, since the others wait for it.
// `control`: a balanced run's, its times and layouts over MPI with the coordinator.
// `windows`: a vnc run's, its desktop over MPI from the coordinator.
int run_mpi_rank(l2::LiveOptions& o, bool tiles, bool control, bool windows,
                 std::chrono::milliseconds start_timeout,
                 std::chrono::milliseconds liveness_timeout) {
#ifdef L2_HAVE_MPI
  l2::MpiSession session(start_timeout, liveness_timeout);
  const l2::CodecTo codec =
      l2::codec_to(o.link_codec, [&session](int rank) { return session.beside(rank); });
  const auto sent = std::make_shared<l2::SentBytes>();
  const auto tiles_sent = std::make_shared<l2::SentBytes>();
  // It lives no longer than the session (MPI_Finalize).
  if (control)
    o.control =
        std::make_shared<l2::MpiControlChannel>(l2::RankMap::kCoordinator, l2::mpi_wire::kControl);
  if (windows)
    o.windows =
        std::make_shared<l2::MpiControlChannel>(l2::RankMap::kCoordinator, l2::mpi_wire::kWindows);
  o.links = [sent, tiles, tiles_sent, control, codec](const l2::TileLayout& layout,
                                                      const l2::PipeserverPlan& plan) {
    l2::MpiRankLinks mpi = l2::mpi_rank_links(layout, plan.pipeserver, codec, sent, control);
    l2::LiveLinks links{nullptr, std::move(mpi.link), std::move(mpi.channel), nullptr};
    if (tiles) {
      links.tiles = std::make_unique<l2::TileSinkOf<l2::MpiTileSender>>(
          l2::MpiTileSender(layout, codec, tiles_sent));
    }
    return links;
  };
  const int code = run_live(o);
  o.control.reset();
  o.windows.reset();
  // Gave up waiting: the coordinator names the cause (another rank) and ends the job.
  if (l2::gave_up_waiting(code)) l2::MpiSession::end_as_effect(code);
  if (code != 0) l2::MpiSession::abort_all(code);
  l2::report_rank_done(*sent, *tiles_sent);
  return 0;
#else
  (void)o;
  (void)tiles;
  (void)control;
  (void)windows;
  (void)start_timeout;
  (void)liveness_timeout;
  std::fprintf(stderr, "pipeserver: --mpi: this pipeserver was built without MPI\n");
  return 2;
#endif
}

}  // namespace

namespace l2 {

int run_pipeserver(int argc, char** argv) {
  CLI::App app{
      "pipeserver: one render node of a Lightning-2 wall. Renders the tiles the wall assigns to\n"
      "the pipeserver numbered --pipeserver with OpenGL, through EGL or OSMesa (--renderer;\n"
      "sort-first: whole-wall camera, per-tile projection), draws the strip headers of spec §4\n"
      "with the parity of --frame, and writes the scanned-out 24-bit RGB frame to --out DIR.\n"
      "--reference writes what each display should show for that frame."};
  Options o;
  l2::add_wall_option(app, o.wall, "default: the built-in default wall (walls/kd-2x2.toml)");
  app.add_option("--pipeserver", o.pipeserver, "pipeserver number, from 0")
      ->check(CLI::Range(0, 4095));
  app.add_option("--frame", o.frame, "application frame number (animation, header parity k mod 2)")
      ->check(CLI::Range(0, 1 << 30));
  app.add_option("--count", o.count,
                 "render frames --frame .. --frame+count-1 (times printed for each); the last is "
                 "written")
      ->check(CLI::Range(1, 100000));
  app.add_option("--scene", o.scene,
                 "mesh | strips | isosurface | patches | swap | picture | movie | session | vnc "
                 "(vnc: under l2wall run only)")
      ->check(CLI::IsMember(l2::scene_names()));
  l2::add_out_option(app, o.out, "scanout-<pipeserver>.png, the scanned-out frame");
  app.add_option("--reference", o.reference,
                 "folder for the reference render of each display (display-<id>.png)")
      ->type_name("DIR");
  const std::vector<l2::SceneOption> scene_options = l2::add_scene_options(app, o.scene_options);
  std::string renderer = "auto";
  app.add_option("--renderer", renderer, l2::kRendererHelp)
      ->check(l2::renderer_choice_check, l2::kRendererChoiceNames)
      ->capture_default_str();
  // Live mode: the run (l2wall run) starts one of these per pipeserver.
  bool live = false;
  l2::LiveOptions live_options;
  auto* group = app.add_option_group(
      "live",
      "live mode, as started by `l2wall run` (DVI link in shared memory, READY on "
      "a serial back-channel)");
  CLI::Option* const live_flag =
      group->add_flag("--live", live,
                      "render --frames frames into the DVI link --link, waiting for READY k-1 on "
                      "--backchannel before publishing frame k");
  group->add_option("--frames", live_options.frames, "live: number of frames")
      ->check(CLI::Range(1, 1 << 30));
  group->add_option("--link", live_options.link, "live: shared-memory name to create (/l2-...)");
  group->add_option("--backchannel", live_options.backchannel,
                    "live: serial device of the back-channel (for example a pty slave)");
  group
      ->add_option("--viz", live_options.viz,
                   "live: host:port of a compositing server; every tile is also sent there "
                   "(its HELLO carries the run token in L2_VIZ_TOKEN, if set)")
      ->check(l2::endpoint_error, "HOST:PORT");
  int control_fd = -1;
  group
      ->add_option("--control-fd", control_fd,
                   "live: inherited socket of the load balancer's control channel (TIMES out, "
                   "LAYOUT in, one line each: balance/)")
      ->check(CLI::Range(3, 1 << 20));
  int windows_fd = -1;
  group
      ->add_option("--windows-fd", windows_fd,
                   "live, --scene session: inherited socket of the run's windows channel (WANT "
                   "out, WINDOWS in, one line each: docs/session-file.md)")
      ->check(CLI::Range(3, 1 << 20));
  group->add_option("--report", live_options.report,
                    "live: file receiving one line per frame (render and READY wait times)");
  l2::add_timeout_option(*group, "ready-timeout", live_options.ready_timeout_ms, false,
                         "per READY wait before asking again with SYNC? (live); a wait for the "
                         "compositing server's SWAPPED (--viz) may last this x (--ready-retries "
                         "+ 1) (l2wall run passes 1000)");
  group
      ->add_option("--ready-retries", live_options.ready_retries,
                   "live: SYNC? retries before giving up")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  bool mpi = false;
  group->add_flag("--mpi", mpi,
                  "live: a rank of `mpirun ... l2wall run --mpi`: frames go to the board column "
                  "ranks and READY comes from the coordinator as MPI messages (instead of "
                  "--link and --backchannel)");
  int mpi_start_timeout_ms = 60000;  // as l2wall run's --start-timeout
  l2::add_timeout_option(*group, "start-timeout", mpi_start_timeout_ms, false,
                         "live, with --mpi: every rank of the run must have joined MPI within "
                         "this, or this rank ends (l2wall run passes its own)");
  int mpi_liveness_timeout_ms = 3000;  // as l2wall run's --liveness-timeout
  l2::add_timeout_option(*group, "liveness-timeout", mpi_liveness_timeout_ms, false,
                         "live, with --mpi: no word from the coordinator for this long ends this "
                         "rank, saying so (l2wall run passes its own)");
  bool mpi_viz = false;
  group->add_flag("--mpi-viz", mpi_viz,
                  "live, with --mpi: also send every tile to the board column rank owning its "
                  "display (the viz path over MPI), waiting for SWAPPED from "
                  "the coordinator");
  bool mpi_windows = false;
  group->add_flag("--mpi-windows", mpi_windows,
                  "live, with --mpi: a vnc run's windows channel as MPI messages with the "
                  "coordinator (WANT out, the desktop's lines in; instead of --windows-fd)");
  bool mpi_control = false;
  group->add_flag("--mpi-control", mpi_control,
                  "live, with --mpi: a balanced run's control channel as MPI messages with the "
                  "coordinator (TIMES out, LAYOUT in; instead of --control-fd); its frames go "
                  "to every board column, since a layout may move its tiles anywhere");
  std::string link_codec = "auto";
  group->add_option("--link-codec", link_codec, "live: " + std::string(l2::link_choice_help()))
      ->check([](const std::string& v) { return l2::parse_link_choice(v).reason(); }, "CODEC")
      ->capture_default_str();
  // Every live option needs --live: without it they were ignored and one frame was written.
  for (CLI::Option* option : group->get_options()) {
    if (option != live_flag) option->needs(live_flag);
  }
  app.callback([&] { l2::check_scene_options(scene_options, o.scene); });
  bool print_gl_info = false;
  app.add_flag("--gl-info", print_gl_info,
               "print the OpenGL version and renderer --renderer decides on here (rendered "
               "pixels depend on them: golden images record them), and why, and exit");
  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;
  o.renderer = l2::parse_renderer_choice(renderer).value();
  if (print_gl_info) {
    try {
      const l2::RendererDecision d = l2::use_renderer(o.renderer);
      const l2::GlInfo gl{d.gl_version, d.gl_renderer};
      std::printf("gl_version: %s\ngl_renderer: %s\nmesa: %s\nrenderer: %s\n", gl.version.c_str(),
                  gl.renderer.c_str(), gl.mesa_version().c_str(), d.line().c_str());
      return 0;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "pipeserver: %s\n", e.what());
      return 1;
    }
  }
  if (live) {
    const bool dvi = !live_options.link.empty() && !live_options.backchannel.empty();
    const bool half_dvi = live_options.link.empty() != live_options.backchannel.empty();
    if (half_dvi || (dvi && mpi) || (!dvi && !mpi && live_options.viz.empty())) {
      std::fprintf(stderr,
                   "pipeserver: --live needs --link with --backchannel, or --mpi, or --viz\n");
      return 2;
    }
    live_options.wall = o.wall;
    live_options.pipeserver = o.pipeserver;
    live_options.scene = o.scene;
    live_options.scene_options = o.scene_options;
    live_options.renderer = o.renderer;
    if (dvi)
      live_options.links = l2::shared_memory_links(live_options.link, live_options.backchannel);
    if (control_fd >= 0) {
      live_options.control = std::make_shared<l2::SocketControlChannel>(l2::Fd(control_fd));
    }
    if (windows_fd >= 0)
      live_options.windows = std::make_shared<l2::SocketControlChannel>(l2::Fd(windows_fd));
    if ((mpi_viz || mpi_control || mpi_windows) && !mpi) {
      std::fprintf(stderr, "pipeserver: --mpi-viz, --mpi-control and --mpi-windows need --mpi\n");
      return 2;
    }
    if (mpi_control && control_fd >= 0) {
      std::fprintf(stderr, "pipeserver: --mpi-control or --control-fd, not both\n");
      return 2;
    }
    live_options.link_codec = l2::parse_link_choice(link_codec).value();
    if (mpi)
      return run_mpi_rank(live_options, mpi_viz, mpi_control, mpi_windows,
                          std::chrono::milliseconds(mpi_start_timeout_ms),
                          std::chrono::milliseconds(mpi_liveness_timeout_ms));
    return run_live(live_options);
  }
  // Its desktop comes from l2wall run's coordinator: alone it would only draw black.
  if (o.scene == "vnc") {
    std::fprintf(stderr,
                 "pipeserver: --scene vnc shows the desktop l2wall run sends; run it through "
                 "l2wall run --scene vnc\n");
    return 2;
  }
  if (o.out.empty() && o.reference.empty()) {
    std::fprintf(stderr, "pipeserver: nothing to do: give --out and/or --reference\n");
    return 2;
  }
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pipeserver: %s\n", e.what());
    return 1;
  }
}

}  // namespace l2
