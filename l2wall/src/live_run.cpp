// The live run's orchestration: which parts run for --path, the refresh loop of the DVI path,
// the swap loop of the vizserver path, what happens on each swap (latency, compare, keep), and
// naming the cause when a process fails. The parts: host_set (pipeservers), dvi_side (the
// emulated Lightning-2), viz_side (the compositing server process), run_pictures, run_report.
#include "live_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "dvi_link/refresh_clock.hpp"
#include "dvi_side.hpp"
#include "host_set.hpp"
#include "image/folders.hpp"
#include "live_show.hpp"
#include "pipeserver/live_exit.hpp"
#include "run_fault.hpp"
#include "run_pictures.hpp"
#include "run_report.hpp"
#include "run_time.hpp"
#include "stop_signal.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "viz_side.hpp"

namespace l2 {
namespace {

using std::chrono::milliseconds;

class LiveRun {
 public:
  explicit LiveRun(const RunOptions& o)
      : o_(o),
        keep_(parse_keep(o.keep)),
        wall_(o.wall.empty() ? default_wall() : load_wall(o.wall)),
        layout_(plan_layout(wall_)),
        records_(static_cast<std::size_t>(o.frames)) {}

  ~LiveRun() { shut_down(); }

  int run() {
    check_options();
    // The planner refused what no run can use (plan_layout); what it only warns of, tilelayout
    // prints too, in the same words.
    for (const std::string& w : layout_.warnings) std::fprintf(stderr, "l2wall: %s\n", w.c_str());
    make_folders(o_.out, "--out");
    remove_earlier_pictures(o_.out);
    if (!o_.show.empty()) show_ = std::make_unique<LiveShow>(o_, wall_);  // before any process
    if (o_.path != "vizserver") dvi_.emplace(wall_, o_.threads, layout_.servers.size());
    if (o_.path != "dvi") viz_ = std::make_unique<VizSide>(viz_launch());
    hosts_.start(host_launch(), layout_);
    if (dvi_) {
      hosts_.open_links(milliseconds(o_.start_timeout_ms), [this] { check_processes(); });
      dvi_loop();
    } else {
      viz_loop();
    }
    if (shown_ < o_.frames) {
      end_at_quit();  // only --show ends the loop early
    } else {
      hosts_.finish(milliseconds(10000));
      if (viz_) viz_->finish(milliseconds(5000));
    }
    write_report();
    return latency_ok_ ? 0 : 1;
  }

  // Whether a progress line is on stderr (an error then starts a line of its own).
  bool progress_shown() const { return progress_shown_; }

  // After a fault: what the displays show now goes to DIR/fault/. False if there was nothing.
  bool save_displays_after_fault() {
    try {
      const auto dir = std::filesystem::path(o_.out) / "fault";
      if (dvi_) write_display_pictures(dir, wall_, dvi_pictures());
      if (viz_ && viz_->last()) {
        write_display_pictures(dir, wall_, viz_pictures(viz_->last()), dvi_ ? "-vizserver" : "");
      }
      return dvi_ || (viz_ && viz_->last());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "l2wall: could not save the displays: %s\n", e.what());
      return false;
    }
  }

  // Ends every process of the run and reaps it; removes the links a dead host left. All are
  // asked first, so their grace periods overlap.
  void shut_down() {
    hosts_.request_stop();
    if (viz_) viz_->shut_down();
    hosts_.shut_down();
  }

 private:
  void check_options() const {
    if (auto error = run_options_error(o_)) throw std::invalid_argument(*error);
  }

  HostLaunch host_launch() const {
    HostLaunch l;
    l.pipeserver = o_.pipeserver;
    l.wall = o_.wall;
    l.scene = o_.scene;
    l.scene_args = o_.scene_args;
    l.out = o_.out;
    l.frames = o_.frames;
    l.ready_timeout_ms = o_.ready_timeout_ms;
    l.dvi = dvi_.has_value();
    if (viz_) {
      l.viz_address = viz_->address();
      l.env.push_back(viz_->token_variable());
    }
    if (show_) l.extra_args = LiveShow::host_args();
    return l;
  }

  VizLaunch viz_launch() const {
    VizLaunch l;
    l.vizserver = o_.vizserver;
    l.host = o_.viz_host;
    l.port = o_.viz_port;
    for (const Display& d : wall_.displays) l.display_sizes.emplace_back(d.width, d.height);
    l.servers = static_cast<int>(layout_.servers.size());
    l.frames = o_.frames;
    l.start_timeout = milliseconds(o_.start_timeout_ms);
    l.log = std::filesystem::path(o_.out) / "vizserver.log";
    return l;
  }

  DisplayPictures dvi_pictures() const {
    return [this](int id) -> const RgbImage& { return dvi_->shown(id); };
  }
  static DisplayPictures viz_pictures(const viz::FramePtr& f) {
    return [f](int id) -> const RgbImage& { return f->displays.at(static_cast<std::size_t>(id)); };
  }

  // --- the DVI path: this process is the Lightning-2 -------------------------------------

  void dvi_loop() {
    RefreshClock clock(o_.refresh_hz);
    bool swap_due = false;
    totals_.start = RunClock::now();
    last_swap_ = totals_.start;
    while (shown_ < o_.frames) {
      if (show_ && !keep_showing()) break;
      if (o_.refresh_hz > 0) clock.wait_next();
      check_processes();
      const bool fresh = dvi_->take_in(hosts_);
      hosts_.serve_channels();
      // As fast as possible still means "when there is something to do": re-reading unchanged
      // links would only take CPU from the hosts.
      if (o_.refresh_hz == 0 && !fresh && !swap_due) {
        check_stall();
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        continue;
      }
      const Emulator::Tick& tick = dvi_->refresh(hosts_, records_);
      swap_due = !tick.completed_groups.empty();
      // READY at once, in the refresh the frame completed (spec §6.4): a host with its next
      // frame rendered swaps it in now, and it is taken in at the next refresh.
      totals_.dropped_readies +=
          static_cast<std::uint64_t>(dvi_->send_readies(tick, hosts_, o_.drop_ready));
      if (!tick.swapped_groups.empty()) on_swap(tick);
      check_stall();
    }
  }

  void on_swap(const Emulator::Tick& tick) {
    const auto now = RunClock::now();
    const int lowest = dvi_->lowest_frame_shown(hosts_);
    dvi_shown_ = std::min(lowest, o_.frames - 1);
    last_swap_ = now;  // the displays swapped: the compositing server's frame is waited from here
    while (shown_ <= lowest && shown_ < o_.frames) {
      FrameRecord& r = records_[static_cast<std::size_t>(shown_)];
      r.shown = true;
      r.swap_refresh = tick.index;
      r.swap_time = now;
      r.writing_ms = writing_ms_;
      r.paused_ms = paused_ms_;
      const long latency = static_cast<long>(r.swap_refresh) - static_cast<long>(r.in_refresh);
      if (latency != 1) {
        latency_ok_ = false;
        std::fprintf(stderr, "\nl2wall: frame %d: latency %ld refreshes, expected 1\n", shown_,
                     latency);
      }
      // Both paths: the compositing server's frame too, every one, compared or not — it waits
      // for us to take its frames before it swaps more.
      if (viz_) {
        const viz::FramePtr f = viz_frame(shown_);
        if (o_.compare) {
          totals_.compared_displays += static_cast<std::uint64_t>(
              compare_paths(shown_, wall_, dvi_pictures(), viz_pictures(f),
                            shown_ == o_.inject_mismatch, o_.out));
        }
      }
      if (keep_.keeps(shown_, o_.frames)) keep_frame(shown_);
      if (shown_ == o_.noise_after) totals_.noise_bytes += hosts_.inject_noise();
      ++shown_;
    }
    // The stall clock restarts once this swap's work is done: the time spent comparing and
    // keeping pictures, or waiting for the compositing server's frame, is not a host's.
    last_swap_ = RunClock::now();
    if (show_ && shown_ > 0) {
      const FrameRecord& r = records_[static_cast<std::size_t>(shown_ - 1)];
      show_->show(shown_ - 1, static_cast<long>(r.swap_refresh) - static_cast<long>(r.in_refresh),
                  dvi_pictures());
    }
    progress(now);
  }

  // --- the vizserver path alone: the compositing server's swaps are the display frames ----

  void viz_loop() {
    totals_.start = RunClock::now();
    totals_.latency_measured = false;
    last_swap_ = totals_.start;
    while (shown_ < o_.frames) {
      viz_frame(shown_);
      const auto now = RunClock::now();
      // Like the DVI path, the clock starts once every host has delivered its first frame.
      if (shown_ == 0) totals_.start = now;
      FrameRecord& r = records_[static_cast<std::size_t>(shown_)];
      r.shown = true;
      r.swap_time = now;
      r.in_time = now;
      r.writing_ms = writing_ms_;
      r.paused_ms = paused_ms_;
      if (keep_.keeps(shown_, o_.frames)) keep_frame(shown_);
      ++shown_;
      last_swap_ = RunClock::now();  // after keeping the frame: that time is not a host's
      progress(now);
    }
  }

  // The compositing server's frame `frame`; while waiting, every process is still watched.
  viz::FramePtr viz_frame(int frame) {
    for (;;) {
      if (viz::FramePtr f = viz_->frame(frame, milliseconds(20))) return f;
      check_processes();
      check_stall();
      hosts_.serve_channels();
    }
  }

  void keep_frame(int frame) {
    const Timed timed(writing_ms_);
    const auto dir = std::filesystem::path(o_.out) / fmt::format("frame-{}", frame);
    // A picture that cannot be written stops the run: the error also says what OUT holds.
    const auto write = [&](const DisplayPictures& pictures, const std::string& suffix) {
      try {
        write_display_pictures(dir, wall_, pictures, suffix);
      } catch (const RunFault&) {
        throw;
      } catch (const std::runtime_error& e) {
        throw partly_written(e, o_.out, fmt::format("the frames kept before frame {}", frame),
                             "no summary.txt or report.csv of this run");
      }
    };
    if (dvi_) write(dvi_pictures(), "");
    if (viz_) write(viz_pictures(viz_frame(frame)), dvi_ ? "-vizserver" : "");
  }

  // --- faults ----------------------------------------------------------------------------

  // A stop signal, a process that ended early, or a compositing server whose stream broke:
  // a RunFault naming the cause.
  void check_processes() {
    check_stop_signal(shown_, displays_kept());
    Host* ended = hosts_.poll_ended();
    const bool viz_down = viz_ && viz_->down();
    if (ended || viz_down) throw RunFault(blame());
  }

  // When one process fails the others lose their connection to it and end too; name the cause.
  // A process killed by a signal is never such an effect. A compositing server that died
  // without saying why is the cause of the pipeservers losing it; one that said why (a
  // pipeserver disconnected) is an effect, its words name the host. One still running that a
  // pipeserver gave up on hangs: it is named, not the pipeserver.
  std::string blame() {
    if (viz_) viz_->settle(milliseconds(300));
    if (Host* killed = hosts_.killed_by_signal())
      return hosts_.describe_end(*killed, displays_kept());
    if (viz_ && viz_->down() && !viz_->said_why())
      return viz_->describe_down(shown_, displays_kept());
    if (Host* ended = hosts_.poll_ended()) {
      // A host that gave up waiting (for READY or SWAPPED) is an effect when another, still
      // there, never delivered the frame everyone waits for: that one stopped answering.
      if (gave_up_waiting(*ended)) {
        if (const Host* hung = hosts_.hung_host(shown_)) {
          return fmt::format(
              "pipeserver {} (pid {}) stopped answering{}: it did not deliver frame {}, and "
              "pipeserver {} gave up {} ({}); {}",
              hung->server, hung->process->pid(), HostSet::stopped_note(*hung), shown_,
              ended->server, waiting_for(*ended), ended->exit->describe(), displays_kept());
        }
      }
      if (lost_a_running_server(*ended)) {
        return fmt::format(
            "the {} stopped answering: pipeserver {} gave up waiting for it at "
            "frame {}; {}",
            viz_->name(), ended->server, shown_, displays_kept());
      }
      return hosts_.describe_end(*ended, displays_kept());
    }
    return viz_ ? viz_->describe_down(shown_, displays_kept())
                : std::string("a process of the run ended");
  }

  static bool gave_up_waiting(const Host& h) {
    return h.exit && h.exit->signal == 0 &&
           (h.exit->code == kExitNoReady || h.exit->code == kExitLostCompositingServer);
  }

  // What a host that gave up was waiting for, by its exit code.
  std::string waiting_for(const Host& h) const {
    if (h.exit->code == kExitNoReady) return "waiting for READY";
    return "waiting for SWAPPED from the " + (viz_ ? viz_->name() : std::string("vizserver"));
  }

  // A host that gave up on a compositing server which is still running: the server hangs (a
  // host waits for SWAPPED only ready-timeout x retries, often less than --stall-timeout).
  bool lost_a_running_server(const Host& h) const {
    return viz_ && !viz_->down() && h.exit && h.exit->code == kExitLostCompositingServer;
  }

  void check_stall() {
    if (shown_ >= o_.frames) return;  // every frame is on the displays: nothing to wait for
    const auto now = RunClock::now();
    // Before the first swap the hosts may still be starting (GL context, first render).
    const int limit_ms = shown_ == 0 ? o_.start_timeout_ms : o_.stall_timeout_ms;
    if (ms_between(last_swap_, now) < limit_ms) return;
    // A host that has not delivered the frame the displays wait for is the one that hangs; if
    // every host delivered it, the compositing server did not.
    std::string culprits = hosts_.late_hosts(shown_);
    // What the hosts that did deliver are doing: waiting for the swap that cannot come.
    std::string note;
    const auto& all = hosts_.hosts();
    const bool some_delivered = std::any_of(
        all.begin(), all.end(), [&](const Host& h) { return hosts_.delivered(h) > shown_; });
    if (const Host* hung = some_delivered ? hosts_.hung_host(shown_) : nullptr) {
      note = fmt::format("{}; the other pipeservers are {}", HostSet::stopped_note(*hung),
                         dvi_ ? "waiting for READY" : "waiting for SWAPPED");
    }
    if (culprits.empty() && viz_) culprits = "the " + viz_->name();
    throw RunFault(fmt::format("no display swap for {} ms: {} did not deliver frame {}{}; {}",
                               limit_ms, culprits.empty() ? "no host" : culprits, shown_, note,
                               displays_kept()));
  }

  // What the displays show now, for a fault message. With both paths they can differ by a
  // frame: the emulator swapped frame K while the run waited for the compositing server's K.
  std::string displays_kept() const {
    const int via_viz = viz_ && viz_->last() ? static_cast<int>(viz_->last()->frame) : -1;
    if (!dvi_ || !viz_ || via_viz == dvi_shown_) {
      const int kept = dvi_ ? dvi_shown_ : via_viz;
      if (kept < 0) return "no frame reached the displays";  // not "frame -1"
      return fmt::format("the displays keep frame {}", kept);
    }
    return fmt::format("the displays keep frame {} (DVI path) and frame {} (vizserver path)",
                       dvi_shown_, via_viz);
  }

  // --- --show ------------------------------------------------------------------------------

  // --show: the keys, and a pause that holds the run (nothing taken in, no READY sent, the
  // hosts wait) while still watching the hosts. False once the user quit and a frame is shown.
  bool keep_showing() {
    const LiveShow::Keys k = show_->keys([this] {
      check_processes();
      hosts_.serve_channels();
    });
    paused_ms_ += static_cast<double>(k.paused.count());  // the hosts wait too: not fps
    last_swap_ += k.paused;                               // nor a stall
    return !(k.quit && shown_ > 0);
  }

  // q / Esc: the frames shown so far are the run, as if --frames had said so. The hosts, still
  // rendering the rest, are stopped; --keep last keeps this frame.
  void end_at_quit() {
    const bool kept = keep_.keeps(shown_ - 1, o_.frames);
    o_.frames = shown_;
    records_.resize(static_cast<std::size_t>(shown_));
    if (!kept && keep_.keeps(shown_ - 1, o_.frames)) keep_frame(shown_ - 1);
    shut_down();
  }

  // --- output ------------------------------------------------------------------------------

  void progress(RunClock::time_point now) {
    if (!o_.progress) return;
    progress_shown_ = true;
    const double s = ms_between(totals_.start, now) / 1000.0;
    std::fprintf(stderr, "\rl2wall: frame %d/%d on the displays, %.1f fps", shown_, o_.frames,
                 s > 0 ? shown_ / s : 0.0);
    std::fflush(stderr);
  }

  void write_report() {
    totals_.refreshes = dvi_ ? dvi_->refreshes() : 0;
    if (dvi_) {
      totals_.frames_predicted = dvi_->emulator_report().frames_predicted;
      totals_.predictions_missed = dvi_->emulator_report().predictions_missed;
    }
    std::vector<std::string> host_logs;
    for (const Host& h : hosts_.hosts()) host_logs.push_back(h.report_path);
    const std::string summary = write_run_report(o_, wall_, host_logs, records_, totals_,
                                                 show_ ? show_->summary(shown_) : std::string());
    if (o_.progress) std::fputs("\n", stderr);
    std::fputs(summary.c_str(), stdout);
  }

  RunOptions o_;
  KeepSet keep_;
  Wall wall_;
  TileLayout layout_;
  std::unique_ptr<LiveShow> show_;  // --show: the displays on screen, keys
  std::optional<DviSide> dvi_;      // --path dvi or both
  std::unique_ptr<VizSide> viz_;    // --path vizserver or both
  HostSet hosts_;                   // after viz_: destroyed first, so hosts end before it
  std::vector<FrameRecord> records_;
  RunTotals totals_;
  bool progress_shown_ = false;
  int shown_ = 0;       // frames 0 .. shown_-1 have reached every display (and were checked)
  int dvi_shown_ = -1;  // the frame the emulator's displays show
  bool latency_ok_ = true;
  double writing_ms_ = 0;  // spent writing kept pictures during the run
  double paused_ms_ = 0;   // spent paused by the --show keys
  RunClock::time_point last_swap_{};
};

}  // namespace

std::optional<std::string> run_options_error(const RunOptions& o) {
  if (o.path != "dvi" && o.path != "vizserver" && o.path != "both")
    return "--path: expected dvi, vizserver or both, got " + o.path;
  if (o.compare && o.path != "both") return "--compare needs --path both";
  if (o.path != "dvi" && o.vizserver.empty())
    return "--vizserver: no compositing server executable given";
  if (o.viz_port < 0 || o.viz_port > 65535)
    return fmt::format("--viz-port: {} is not 0..65535", o.viz_port);
  // There is no compositing server on the DVI path: an address for it would go unused.
  if (o.path == "dvi" && (o.viz_port != 0 || o.viz_host != RunOptions{}.viz_host))
    return "--viz-host and --viz-port need --path vizserver or both";
  KeepSet keep;
  try {
    keep = parse_keep(o.keep);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  // A frame the run never renders would silently keep nothing, or inject no fault, and the
  // run would pass as if the fault had been survived.
  const auto past_the_last = [&o](const char* option, int frame) -> std::optional<std::string> {
    if (frame < o.frames) return std::nullopt;
    return fmt::format("{}: frame {} is past the last frame (--frames {} renders 0..{})", option,
                       frame, o.frames, o.frames - 1);
  };
  if (!keep.frames.empty()) {
    if (auto error = past_the_last("--keep", *keep.frames.rbegin())) return error;
  }
  for (const auto& [option, frame] : {std::pair{"--inject-noise", o.noise_after},
                                      std::pair{"--inject-mismatch", o.inject_mismatch},
                                      std::pair{"--drop-ready", o.drop_ready}}) {
    if (auto error = past_the_last(option, frame)) return error;
  }
  if (o.inject_mismatch >= 0 && !o.compare) return "--inject-mismatch needs --compare";
  return std::nullopt;
}

int run_wall(const RunOptions& options) {
  catch_stop_signals();
  std::unique_ptr<LiveRun> run;
  try {
    run = std::make_unique<LiveRun>(options);
    return run->run();
  } catch (const RunFault& e) {
    if (run && run->progress_shown()) std::fputs("\n", stderr);
    std::fprintf(stderr, "l2wall: %s\n", e.what());
    if (run) {
      if (run->save_displays_after_fault())
        std::fprintf(stderr, "l2wall: displays as they were: %s/fault/\n", options.out.c_str());
      run->shut_down();
    }
    return 1;
  } catch (const std::exception& e) {
    if (run && run->progress_shown()) std::fputs("\n", stderr);
    std::fprintf(stderr, "l2wall: %s\n", e.what());
    return 1;
  }
}

}  // namespace l2
