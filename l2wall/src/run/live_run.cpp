#include "l2wall/live_run.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "frame_loop.hpp"
#include "image/folders.hpp"
#include "l2wall/run_backends.hpp"
#include "l2wall/run_fault.hpp"
#include "l2wall/stop_signal.hpp"
#include "page_steering.hpp"
#include "pipeserver/picture_cache.hpp"
#include "progress_line.hpp"
#include "run_core.hpp"
#include "run_windows.hpp"
#include "run_writer.hpp"
#include "tilelayout/dvi_timing.hpp"
#include "touch_steering.hpp"
#include "vizserver_process.hpp"
#include "watchdog.hpp"

namespace l2 {
namespace {

using std::chrono::milliseconds;

// `l2wall run`'s live run, made of separately filed parts, each with its contract in its class
// comment: the frame loop (frame_loop.hpp), the watchdog (watchdog.hpp), page steering
// (page_steering.hpp), the windows and desktops (run_windows.hpp), touch steering
// (touch_steering.hpp), the report writer
// (run_writer.hpp) and the progress line (progress_line.hpp), all working on the run's core
// (run_core.hpp). LiveRun owns them and the run's order: which display paths run for --path, the
// pipeservers started, the frames, and the end, well or in a fault, with every process ended.
// It alone makes the paths and starts and ends the run's processes; what happens between the
// first frame and the last is the parts'.
class LiveRun {
 public:
  LiveRun(const RunOptions& o, const RunBackends& backends) : core_(o), backends_(backends) {}
  ~LiveRun() { shut_down(); }

  int run();
  bool progress_shown() const { return progress_.shown(); }
  std::optional<std::string> save_displays_after_fault() {
    return writer_.save_displays_after_fault();
  }
  void write_report_after_fault(const std::string& fault);
  // Ends every process of the run and reaps it; removes the links a dead pipeserver left. All
  // are asked first, so their grace periods overlap.
  void shut_down() {
    core_.pipeservers.request_stop();
    for (auto& p : core_.paths) p->shut_down();
    core_.pipeservers.shut_down();
  }

 private:
  void prepare();
  void cap_refresh_at_the_link();
  void make_paths();
  void start_balance();
  void start_pipeservers();
  void end_frames();
  int exit_status() const;
  PipeserverLaunch launch_pipeservers() const;
  VizLaunch viz_launch() const;
  std::string write_report(const std::string& fault);

  RunCore core_;
  const RunBackends& backends_;
  ProgressLine progress_{core_};
  RunWindows windows_;
  TouchSteering touch_;
  Watchdog watchdog_{core_, progress_};
  // A session's windows and a vnc run's desktop are served with the processes: WANT comes
  // before each READY wait.
  const RunWatch watch_{[this] {
                          watchdog_.check_processes();
                          windows_.serve(core_.pipeservers);
                          if (!core_.frames.links_open) progress_.waiting();
                        },
                        [this] {
                          watchdog_.check_processes();
                          watchdog_.check_stall();
                          core_.pipeservers.serve_channels();
                          windows_.serve(core_.pipeservers);
                        }};
  RunWriter writer_{core_, watch_};
  PageSteering steering_{core_,    watch_,  watchdog_,
                         windows_, writer_, backends_.stops_pipeservers_early()};
  FrameLoop loop_{core_, watch_, {watchdog_, steering_, windows_, touch_, writer_, progress_}};
};

int LiveRun::run() {
  prepare();
  loop_.open_show();                  // before any process
  if (!core_.options.http.empty()) {  // a taken port too
    core_.page =
        std::make_unique<LivePage>(core_.options, core_.wall, backends_.stops_pipeservers_early());
  }
  touch_.start(core_.options.tuio, core_.wall);  // a taken port too, before any process
  make_paths();
  start_balance();
  windows_.start(core_.options, core_.layout, core_.balance != nullptr);
  start_pipeservers();
  for (auto& p : core_.paths)
    p->open(core_.pipeservers, milliseconds(core_.options.start_timeout_ms), watch_);
  // From here on the clock runs; a pipeserver lost before (--survive-host-loss) was waited for
  // by no one.
  core_.frames.links_open = true;
  loop_.run_until_stopped();
  end_frames();
  const std::string summary = write_report("");
  steering_.end(summary.substr(0, summary.find('\n')), summary);
  return exit_status();
}

// The options, the plan's warnings, the refresh rate and OUT, before anything starts.
void LiveRun::prepare() {
  const RunOptions& o = core_.options;
  if (const Status s = run_options_error(o); !s.ok()) throw std::invalid_argument(s.reason());
  if (const Status s = balance_refusal(o, core_.wall, RunPlace::OneMachine); !s.ok())
    throw LayoutError(s.reason());
  if (const Status s = stereo_refusal(o, core_.wall); !s.ok()) throw LayoutError(s.reason());
  // The planner refused what no run can use (plan_layout); what it only warns of, tilelayout
  // prints too, in the same words.
  for (const std::string& w : core_.layout.warnings)
    std::fprintf(stderr, "l2wall: %s\n", w.c_str());
  cap_refresh_at_the_link();
  make_folders(o.out, "--out");
  // A read-only OUT is found now, not by each pipeserver opening its log in it.
  check_folder_writable(o.out, "--out");
  remove_earlier_pictures(o.out);
}

// A DVI link carries no more refreshes than its pixel clock allows (dual link, CVT reduced
// blanking): asked for more, the emulator refreshes as fast as the link could carry frames.
void LiveRun::cap_refresh_at_the_link() {
  RunOptions& o = core_.options;
  if (o.refresh_hz <= 0) return;
  const int w = core_.wall.framebuffer_width, h = core_.wall.framebuffer_height;
  const int most = max_refresh_hz(w, h, kDualLinkDviMhz);
  if (o.refresh_hz <= most) return;
  std::fprintf(stderr,
               "l2wall: warning: framebuffers of %dx%d at %g Hz need a %.2f MHz pixel clock, "
               "more than dual-link DVI carries (%g MHz): the emulator refreshes at %d Hz\n",
               w, h, o.refresh_hz, dvi_timing(w, h, static_cast<int>(o.refresh_hz)).pixel_clock_mhz,
               kDualLinkDviMhz, most);
  o.refresh_hz = most;
}

// The lead path first: the DVI path when it runs (its refreshes pace the run), beside it the
// compositing server, whose frames are taken (and compared) as the lead swaps.
void LiveRun::make_paths() {
  if (runs_dvi(core_.options.path))
    core_.paths.push_back(backends_.dvi_path(core_.layout, core_.options));
  if (runs_viz(core_.options.path))
    core_.paths.push_back(backends_.viz_path(core_.layout, viz_launch()));
}

// A balanced run: the coordinator, and the lead path following its layouts.
void LiveRun::start_balance() {
  const BalanceSpec spec = run_balance(core_.options, core_.wall);
  if (!spec.balancing()) return;
  Wall wall = core_.wall;
  wall.balance = spec;
  core_.balance = std::make_unique<LiveBalance>(wall, balance_settings(wall), core_.layout,
                                                core_.options.frames);
  if (const std::string note = survival_note(core_.options, core_.wall); !note.empty())
    std::fprintf(stderr, "l2wall: %s\n", note.c_str());
  core_.lead().follow_layouts(*core_.balance, core_.pipeservers);
}

void LiveRun::start_pipeservers() {
  backends_.start_pipeservers(core_.pipeservers, launch_pipeservers(), core_.layout);
  core_.frames.pipeservers_started = true;
  steering_.watch_pipeservers();
}

PipeserverLaunch LiveRun::launch_pipeservers() const {
  PipeserverLaunch l = pipeserver_launch(core_.options);
  add_picture_cache_default(l, static_cast<int>(core_.layout.pipeservers.size()),
                            physical_memory_mb());
  for (const auto& p : core_.paths) p->add_pipeserver_args(l);
  l.extra_args = pausable_pipeserver_args(core_.options);
  l.control = core_.balance != nullptr;
  l.windows = windows_.any();  // a vnc run's desktop goes there
  return l;
}

VizLaunch LiveRun::viz_launch() const {
  const RunOptions& o = core_.options;
  VizLaunch l;
  l.program = o.vizserver_program;
  l.host = o.viz_host;
  l.port = o.viz_port;
  for (const Display& d : core_.wall.displays) l.display_sizes.emplace_back(d.width, d.height);
  l.pipeservers = static_cast<int>(core_.layout.pipeservers.size());
  l.frames = o.frames;
  l.start_timeout = milliseconds(o.start_timeout_ms);
  l.log = std::filesystem::path(o.out) / "vizserver.log";
  l.survive_losses = run_balance(o, core_.wall).survive_host_loss;
  return l;
}

// Every frame shown: the processes end by themselves. Cut short (q under --show, a stop from the
// page, a stop signal): the frames shown are the run, the processes are ended.
void LiveRun::end_frames() {
  if (core_.frames.shown < core_.options.frames) {
    loop_.cut_at_shown();
    shut_down();
  } else {
    core_.pipeservers.finish(milliseconds(10000));
    for (auto& p : core_.paths) p->finish();
  }
}

// After the report: 0 when every frame reached the displays with one frame of latency.
int LiveRun::exit_status() const {
  const int stopped = core_.frames.stopped;
  if (!stopped) return core_.frames.latency_ok ? 0 : 1;
  std::fprintf(stderr, "l2wall: stopped by signal %d (%s) after %d frames; report: %s\n", stopped,
               strsignal(stopped), core_.frames.shown, core_.options.out.c_str());
  return stopped_exit_status(stopped);
}

// `fault`: the fault that ended the run at the frames shown, or empty. Returns the summary.
std::string LiveRun::write_report(const std::string& fault) {
  const std::string extra =
      loop_.show_summary() + steering_.summary() +
      (core_.balance ? core_.balance->summary(core_.frames.shown) : std::string()) +
      windows_.summary() + touch_.summary();
  std::vector<std::pair<std::string, std::string>> files;
  if (core_.balance) files.emplace_back("layouts.txt", core_.balance->layouts());
  for (auto& file : windows_.files()) files.push_back(std::move(file));
  return writer_.write_report(fault, extra, std::move(files));
}

// After a fault, once every process is ended (their logs are complete): report.csv and
// summary.txt of the frames that reached the displays before it, the summary's first line naming
// the fault; the summary printed as at a run's end. Nothing when the pipeservers had not
// started: nothing was measured.
void LiveRun::write_report_after_fault(const std::string& fault) {
  std::string summary;
  FrameLedger& f = core_.frames;
  if (f.pipeservers_started) {
    try {
      core_.options.frames = f.shown;
      f.records.resize(static_cast<std::size_t>(f.shown));
      summary = write_report(fault);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "l2wall: could not write the report: %s\n", e.what());
    }
  }
  if (core_.page) {
    core_.page->event(f.shown - 1, fault);
    core_.page->end("ended in a fault: " + fault, summary);
  }
}

}  // namespace

int run_wall(const RunOptions& options) {
  return run_wall(options, one_machine_backends());
}

int run_wall(const RunOptions& options, const RunBackends& backends) {
  catch_stop_signals();
  std::unique_ptr<LiveRun> run;
  try {
    run = std::make_unique<LiveRun>(options, backends);
    return run->run();
  } catch (const RunFault& e) {
    if (run && run->progress_shown()) std::fputs("\n", stderr);
    if (!backends.fault_said(e.what())) std::fprintf(stderr, "l2wall: %s\n", e.what());
    if (run) {
      if (const auto note = run->save_displays_after_fault())
        std::fprintf(stderr, "l2wall: displays as they were: %s/fault/%s\n", options.out.c_str(),
                     note->c_str());
      run->shut_down();
      run->write_report_after_fault(e.what());
    }
    const int signal = stop_signal_received();
    return signal ? stopped_exit_status(signal) : 1;
  } catch (const std::exception& e) {
    if (run && run->progress_shown()) std::fputs("\n", stderr);
    std::fprintf(stderr, "l2wall: %s\n", e.what());
    return 1;
  }
}

}  // namespace l2
