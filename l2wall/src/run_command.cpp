#include "run_command.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "command_line/checks.hpp"
#include "command_line/options.hpp"
#include "command_line/program_paths.hpp"
#include "control_page/http_address.hpp"
#include "dvi_link/frame_delta.hpp"
#include "image/movie_file.hpp"
#include "image/picture_regions.hpp"
#include "image/tiled_copy.hpp"
#include "l2wall/live_run.hpp"
#include "l2wall/stop_signal.hpp"
#include "pipeserver/model_file.hpp"
#include "pipeserver/renderer_choice.hpp"
#include "pipeserver/scene_cli.hpp"
#include "report_plot.hpp"
#include "tilelayout/wall.hpp"

#ifdef L2_HAVE_MPI
#include "l2wall/mpi_run.hpp"
#endif

namespace l2 {
namespace {

// Everything `l2wall run` is told, kept until its callback runs.
struct RunCommand {
  RunOptions o;
  SceneOptions scene;
  std::vector<SceneOption> scene_options;
  std::string path;  // --path as typed
  bool mpi = false;
  bool plot = false;
};

int plot_run(const std::string& dir) {
  try {
    std::printf("plot: %s\n", plot_report(dir).c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "l2wall plot: %s\n", e.what());
    return 1;
  }
}

Status mpi_error(const RunOptions& o) {
#ifdef L2_HAVE_MPI
  return mpi_options_error(o);
#else
  (void)o;
  return Failure{"--mpi: this l2wall was built without MPI"};
#endif
}

int run_over_mpi(const RunOptions& o) {
#ifdef L2_HAVE_MPI
  return run_wall_mpi(o);
#else
  (void)o;
  std::fprintf(stderr, "l2wall: --mpi: this l2wall was built without MPI\n");
  return 1;
#endif
}

// What is said once for the run: under mpirun every rank runs the checks, and rank 0 says it.
void tell_once(bool mpi, const std::string& line) {
  if (line.empty()) return;
#ifdef L2_HAVE_MPI
  if (mpi && !coordinator_rank()) return;
#else
  (void)mpi;
#endif
  std::printf("%s\n", line.c_str());
}

// The wall, what it shows, how many frames, and which of them are kept.
void add_wall_options(CLI::App& run, RunCommand& c) {
  RunOptions& o = c.o;
  add_wall_option(run, o.wall,
                  "default: the built-in default wall (walls/kd-2x2.toml: 4 pipeservers, "
                  "2x2 displays)");
  run.add_option("--scene", o.scene,
                 "mesh | strips | isosurface | patches | swap | picture | movie | session | vnc")
      ->check(CLI::IsMember(scene_names()))
      ->capture_default_str();
  run.add_option("--vnc-password-file", o.vnc_password_file,
                 "vnc scene: the server's password, in the file `vncpasswd -f` writes (as "
                 "Xvnc -PasswordFile and x11vnc -rfbauth read it)")
      ->check(CLI::ExistingFile);
  run.add_option("--frames", o.frames,
                 "application frames to render (on an active stereo wall eye frames, an even "
                 "count: 2k the left eye of frame k, 2k+1 its right)")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  add_out_option(run, o.out,
                 "frame-<k>/display-<id>.png and wall.png for kept frames, report.csv (one "
                 "row per frame), summary.txt, pipeserver-<i>.log, vizserver.log (the compositing "
                 "server's lines), layouts.txt (--balance: each frame's layout), "
                 "frame-lock.csv (a wall with [displays] clocks: per refresh each display's frame "
                 "counter and the frame it showed), stereo-refreshes.csv (an active stereo wall: "
                 "per refresh the eye shown and its frame)")
      ->capture_default_str();
  run.add_option("--keep", o.keep,
                 "frames whose displays are written: every | last | none | K,L,...")
      ->capture_default_str();
  add_refresh_option(run, o.refresh_hz, true,
                     "emulator input refreshes per second; 0 = as fast as possible")
      ->capture_default_str();
}

// The display paths, balancing and survival, and comparing the paths.
void add_path_options(CLI::App& run, RunCommand& c) {
  RunOptions& o = c.o;
  c.path = std::string(path_choice_name(o.path));
  run.add_option("--path", c.path,
                 "dvi: DVI links in shared memory and the emulated Lightning-2; vizserver: "
                 "tiles read back and sent over TCP to a compositing server process "
                 "(--vizserver-program), which streams the composed displays back to l2wall; both: "
                 "both at once")
      ->check(
          [](const std::string& v) {
            return parse_path_choice(v) ? std::string()
                                        : "expected dvi, vizserver or both, got " + v;
          },
          "dvi|vizserver|both")
      ->each([&choice = o.path](const std::string& v) { choice = parse_path_choice(v).value(); })
      ->capture_default_str();
  run.add_option("--balance", o.balance,
                 "re-tile live from the last frame's render times, over the wall file's "
                 "[balance] mode: static (the wall's tiling), strips (horizontal strips with "
                 "vertical sub-strips moving toward equal load) or kd (the k-d tiling re-cut "
                 "over a cost grid); on every --path, also with --mpi (docs/wall-file.md)")
      ->check(CLI::IsMember(
          std::vector<std::string>(std::begin(kBalanceModeNames), std::end(kBalanceModeNames))));
  run.add_option("--resistance", o.resistance,
                 "with balancing: take a new layout only when it is predicted to shorten the "
                 "frame by this fraction (0 up to below 1; over [balance] resistance; the "
                 "summary counts the layouts not taken)")
      ->check(CLI::Range(0.0, 0.999));
  run.add_option("--tile-cost", o.tile_cost,
                 "with --resistance: a display tile's fixed part in that prediction, as a "
                 "fraction of the mean tile time (0 up to below 1; over [balance] tile_cost)")
      ->check(CLI::Range(0.0, 0.999));
  run.add_flag("--survive-host-loss", o.survive_host_loss,
               "with balancing: a pipeserver that dies (killed, crashed, exited) does not end "
               "the run; its tiles go to the others from the next layout on, and the summary "
               "names it and counts the frames shown stale meanwhile (as [balance] "
               "survive_host_loss = true; without it a dead pipeserver ends the run, named); "
               "--path dvi or vizserver; with --mpi, a pipeserver rank, under an mpirun that "
               "keeps the job (mpirun --mca orte_enable_recovery 1 --mca "
               "orte_abort_on_non_zero_status 0)");
  run.add_flag("--compare", o.compare,
               "with --path both: every display must be identical byte for byte on both paths; "
               "a mismatch writes both pictures and a diff picture to "
               "DIR/mismatch-frame-<k>/ and fails the run");
}

// The programs the run starts, where the compositing server listens, and how long the run
// waits for its processes.
void add_process_options(CLI::App& run, RunCommand& c) {
  RunOptions& o = c.o;
  run.add_option("--pipeserver-program", o.pipeserver_program, "the pipeserver executable")
      ->capture_default_str();
  // Checked here as every pipeserver checks it, and passed on to each (on every machine of an
  // MPI run).
  run.add_option("--renderer", o.renderer, kRendererHelp)
      ->check(renderer_choice_check, kRendererChoiceNames)
      ->capture_default_str();
  run.add_option("--vizserver-program", o.vizserver_program,
                 "the compositing server executable of --path vizserver|both; l2wall starts "
                 "it as its own process, and a compositing server that dies ends the run like "
                 "a pipeserver that dies")
      ->capture_default_str();
  run.add_option("--viz-host", o.viz_host,
                 "address the compositing server listens on for tiles (0.0.0.0: every "
                 "interface, so pipeservers on other machines can reach it)")
      ->capture_default_str();
  run.add_option("--viz-port", o.viz_port,
                 "TCP port the compositing server listens on; 0 = a free one, which it reports "
                 "to l2wall before any pipeserver starts")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  add_threads_option(run, o.threads);
  add_timeout_option(run, "start-timeout", o.start_timeout_ms, false,
                     "until every pipeserver must have published its first frame (with "
                     "--mpi, also until every rank has joined MPI)");
  add_timeout_option(run, "stall-timeout", o.stall_timeout_ms, false,
                     "without a display swap after which the run names the hung pipeserver "
                     "(or compositing server) and stops");
  add_timeout_option(run, "liveness-timeout", o.liveness_timeout_ms, false,
                     "with --mpi: a rank that sends no word for this long (each sends one every "
                     "200 ms), its host's network down, is named and ends the run (or is "
                     "survived, --survive-host-loss); a rank that hears nothing from the "
                     "coordinator for this long ends, saying so");
  add_timeout_option(run, "ready-timeout", o.ready_timeout_ms, false,
                     "a pipeserver waits for READY before asking again with SYNC?");
  // A plain flag: CLI11 2.1 lists a negated one as "--no-progress{false}".
  run.add_flag_callback(
      "--no-progress", [&o] { o.progress = false; },
      "no progress line on stderr (there is one only when stderr is a terminal: none in a log "
      "file or through mpirun)");
}

// Watching and steering the run: on screen, from stdin, from the control page.
void add_watch_options(CLI::App& run, RunCommand& c) {
  RunOptions& o = c.o;
  run.add_option("--show", o.show,
                 "put the displays on screen as they swap (needs an X display; without one, "
                 "run under Xvfb). window: one window laying out the wall as the wall file "
                 "places it, mullions dark, overlay line with frame, fps and latency. monitors: "
                 "each display fullscreen on the monitor its wall-file `monitor` names. Keys: "
                 "space pauses the run (READY is held back, the pipeservers wait), s saves a "
                 "screenshot of every display to OUT/screenshots/, q or Esc ends the run as "
                 "after its last frame. With --mpi: monitors only, each board column rank "
                 "showing its own displays on its machine's DISPLAY; no keys")
      ->check(CLI::IsMember({"window", "monitors"}));
  run.add_flag("--window-stdin", o.window_stdin,
               "with --scene session: take window commands from stdin, one a line: 'move ID X Y "
               "W H', 'raise ID', 'close ID', each on every pipeserver from the same frame "
               "(docs/session-file.md); what was taken or why not goes to stderr");
  run.add_option("--tuio", o.tuio,
                 "with --scene session: take multi-touch over TUIO 1.1 (/tuio/2Dcur, OSC over "
                 "UDP; trackers send to port 3333) at [ADDR:]PORT (ADDR: 127.0.0.1, this "
                 "machine only, unless given; PORT 0: a free one, printed at start): a tap "
                 "raises the window under the finger, one finger drags it, two pinch it about "
                 "their centre, each as a window command said on stderr (docs/session-file.md). "
                 "Without --tuio no socket is opened and touch steers nothing")
      ->check([](const std::string& v) { return parse_http_address(v).reason(); }, "[ADDR:]PORT");
  run.add_option("--http", o.http,
                 "serve a control page for the run at [ADDR:]PORT (ADDR: 127.0.0.1, this "
                 "machine only, unless given; PORT 0: a free one): the wall with each display's "
                 "picture a few times a second, frame, fps, latency, what limits the run, every "
                 "pipeserver's times, the current tiles and events; buttons to pause, resume, "
                 "save the displays (OUT/frame-N/) and stop, and the balance mode of a balanced "
                 "run; in a session with `shares`, a browser's screen shared as a window. Its URL, "
                 "printed at start, carries the run's token, which every control "
                 "(and, bound beyond 127.0.0.1, every read) needs (control_page/README.md)")
      ->check([](const std::string& v) { return parse_http_address(v).reason(); }, "[ADDR:]PORT");
  run.add_option("--show-readback", o.show_readback,
                 "verification aid for --show: after every presented frame, read the windows "
                 "back from the X server and write DIR/frame-<k>/display-<id>.png (what the "
                 "screen shows of each display) and window-<i>.png; slows the run")
      ->needs(run.get_option("--show"));
}

// Fault injection, MPI, and how frames travel.
void add_fault_options(CLI::App& run, RunCommand& c) {
  RunOptions& o = c.o;
  run.add_option("--inject-noise", o.noise_after,
                 "fault injection: after frame K reaches the displays, write line noise to "
                 "every back-channel")
      ->check(CLI::Range(0, 1000000));
  run.add_option("--inject-mismatch", o.inject_mismatch,
                 "fault injection: with --compare, change one pixel of display 0 of frame K on "
                 "the vizserver side before comparing")
      ->check(CLI::Range(0, 1000000));
  run.add_option("--drop-ready", o.drop_ready,
                 "fault injection: hold back the READY of frame K to pipeserver 0 until it "
                 "asks with SYNC?")
      ->check(CLI::Range(0, 1000000));
  run.add_flag("--mpi", c.mpi,
               "run the wall over MPI ranks: mpirun -np N l2wall run --wall WALL --mpi, N = 1 "
               "coordinator + one rank per pipeserver + one per board column of the mesh, in "
               "that rank order (docs/mpi-design.md); frames and READY travel as MPI messages");
  run.add_option("--link-codec", o.link_codec, std::string(link_choice_help()))
      ->check([](const std::string& v) { return parse_link_choice(v).reason(); }, "CODEC")
      ->capture_default_str();
}

// Options that make no run together are usage errors too (exit 2), not a failed run.
void check_run_options(CLI::App& run, RunCommand& c) {
  RunOptions& o = c.o;
  if (const Status s = run_options_error(o); !s.ok()) throw CLI::ValidationError(s.reason());
  if (const Status s = c.mpi ? mpi_error(o) : Status{}; !s.ok())
    throw CLI::ValidationError(s.reason());
  check_scene_options(c.scene_options, o.scene);
  o.scene_args = scene_arguments(c.scene_options);
  // A movie plays by its own clock at the wall's refresh rate unless told otherwise; at full
  // speed there is no clock to play by.
  if ((o.scene == "movie" || o.scene == "session") && run.count("--movie-rate") == 0)
    o.scene_args.insert(o.scene_args.end(), {"--movie-rate", fmt::format("{:g}", o.refresh_hz)});
}

// Content that every pipeserver would refuse is refused here in one line, before any starts.
void check_content(const RunCommand& c) {
  const RunOptions& o = c.o;
  // What of a model is left out is said here once, not by every pipeserver.
  if (o.scene == "mesh" && !c.scene.mesh_file.empty())
    tell_once(c.mpi, check_model(c.scene.mesh_file));
  if (o.scene == "movie") MovieFile(c.scene.content).frame(0);
  // A session is read whole, every window's source with it: a wrong line or file is one line
  // here, not one from every pipeserver.
  if (o.scene == "session") tell_once(c.mpi, make_scene("session", c.scene)->note());
}

// The run's options with the picture every pipeserver reads: a picture stored as scanlines
// too large to hold decoded (past the picture cache's limit) is copied tiled now, before the
// run's clock starts (image/tiled_copy.hpp), and the pipeservers are given the copy.
RunOptions with_picture_to_read(const RunCommand& c) {
  RunOptions o = c.o;
  if (o.scene != "picture") return o;
  const double limit =
      c.scene.picture_cache_mb > 0 ? c.scene.picture_cache_mb : kDefaultPictureCacheMegabytes;
  const std::filesystem::path read = picture_to_read(c.scene.content, limit);
  PictureRegions{read, limit};
  const auto at = std::find(o.scene_args.begin(), o.scene_args.end(), "--content");
  if (at != o.scene_args.end() && at + 1 != o.scene_args.end()) *(at + 1) = read.string();
  return o;
}

int run_command(const RunCommand& c) {
  try {
    check_content(c);
    const RunOptions o = with_picture_to_read(c);
    const int status = c.mpi ? run_over_mpi(o) : run_wall(o);
    // A run stopped by a signal wrote its report too (stop_signal.hpp).
    const bool reported = status == 0 || status == stopped_exit_status(SIGINT);
    if (c.plot && reported) {
      if (const int plotted = plot_run(c.o.out); plotted != 0) return plotted;
    }
    return status;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "l2wall: %s\n", e.what());
    return 1;
  }
}

void add_plot_command(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  CLI::App* plot = app.add_subcommand(
      "plot",
      "draw the report.csv of a run as DIR/report.png with gnuplot: per frame the emulator's "
      "route and swap time and every pipeserver's render time, titled with what limited the run");
  plot->add_option("DIR", *dir, "the --out folder of an `l2wall run`")
      ->required()
      ->check(CLI::ExistingDirectory);
  plot->callback([dir] { throw CLI::RuntimeError(plot_run(*dir)); });
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto c = std::make_shared<RunCommand>();
  c->o.pipeserver_program = sibling_program("pipeserver").string();
  c->o.vizserver_program = sibling_program("vizserver").string();
  CLI::App* run = app.add_subcommand(
      "run",
      "render --frames frames on the wall and write the displays, a per-frame report and a "
      "summary to --out");
  add_wall_options(*run, *c);
  add_path_options(*run, *c);
  add_process_options(*run, *c);
  add_watch_options(*run, *c);
  add_fault_options(*run, *c);
  // The scene and camera options of pipeserver, passed on to every pipeserver as typed.
  c->scene_options = add_scene_options(*run, c->scene);
  run->add_flag("--plot", c->plot,
                "after the run, draw report.csv as OUT/report.png (as `l2wall plot OUT` does)");
  run->callback([c, run] {
    check_run_options(*run, *c);
    throw CLI::RuntimeError(run_command(*c));
  });
  add_plot_command(app);
}

}  // namespace l2
