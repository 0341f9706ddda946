// The live run's orchestration: which display paths run for --path, the loop of the lead path's
// swaps, what happens on each swap (latency, compare, saved frames), and naming the cause when a
// process fails. The parts: pipeserver_set, the display paths behind display_path.hpp
// (dvi_path: the emulated Lightning-2; viz_path: the compositing server process), run_pictures,
// run_report.
#include "l2wall/live_run.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "desktops/live_desktop.hpp"
#include "desktops/live_windows.hpp"
#include "desktops/session_desktops.hpp"
#include "image/folders.hpp"
#include "l2wall/display_path.hpp"
#include "l2wall/live_balance.hpp"
#include "l2wall/live_show.hpp"
#include "l2wall/pipeserver_set.hpp"
#include "l2wall/run_backends.hpp"
#include "l2wall/run_fault.hpp"
#include "l2wall/run_pictures.hpp"
#include "l2wall/run_report.hpp"
#include "l2wall/run_time.hpp"
#include "l2wall/stall_verdict.hpp"
#include "line_reader.hpp"
#include "live_page.hpp"
#include "pipeserver/live_exit.hpp"
#include "stop_signal.hpp"
#include "tilelayout/dvi_timing.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/session_file.hpp"
#include "tilelayout/wall_file.hpp"
#include "vizserver_process.hpp"

namespace l2 {
namespace {

using std::chrono::milliseconds;

class LiveRun {
 public:
  LiveRun(const RunOptions& o, const RunBackends& backends)
      : o_(o),
        backends_(backends),
        saved_(parse_saved_frames(o.keep)),
        wall_(o.wall.empty() ? default_wall() : load_wall(o.wall)),
        layout_(plan_layout(wall_)),
        records_(static_cast<std::size_t>(o.frames)) {
    // A line redrawn with \r is for a terminal: in a log file, or through mpirun, it is one
    // line growing by a frame at every swap.
    o_.progress = o_.progress && isatty(STDERR_FILENO) == 1;
  }

  ~LiveRun() { shut_down(); }

  int run() {
    check_options();
    // The planner refused what no run can use (plan_layout); what it only warns of, tilelayout
    // prints too, in the same words.
    for (const std::string& w : layout_.warnings) std::fprintf(stderr, "l2wall: %s\n", w.c_str());
    cap_refresh_at_the_link();
    make_folders(o_.out, "--out");
    // A read-only OUT is found now, not by each pipeserver opening its log in it.
    check_folder_writable(o_.out, "--out");
    remove_earlier_pictures(o_.out);
    if (!o_.show.empty()) show_ = std::make_unique<LiveShow>(o_, wall_);  // before any process
    if (!o_.http.empty())
      page_ = std::make_unique<LivePage>(o_, wall_,
                                         backends_.stops_pipeservers_early());  // a taken port too
    make_paths();
    start_balance();
    start_windows();
    start_desktop();
    backends_.start_pipeservers(pipeservers_, launch_pipeservers(), layout_);
    pipeservers_started_ = true;
    if (page_) watch_pipeservers_on_the_page();
    for (auto& p : paths_) p->open(pipeservers_, milliseconds(o_.start_timeout_ms), watch_);
    // From here on the clock runs; a pipeserver lost before (--survive-host-loss) was waited for
    // by no one.
    links_open_ = true;
    run_frames_until_stopped();
    if (shown_ < o_.frames) {
      end_at_quit();  // q under --show, or a stop signal
    } else {
      pipeservers_.finish(milliseconds(10000));
      for (auto& p : paths_) p->finish();
    }
    const std::string summary = write_report("");
    if (page_) page_->end(summary.substr(0, summary.find('\n')), summary);
    if (stopped_) {
      std::fprintf(stderr, "l2wall: stopped by signal %d (%s) after %d frames; report: %s\n",
                   stopped_, strsignal(stopped_), shown_, o_.out.c_str());
      return stopped_exit_status(stopped_);
    }
    return latency_ok_ ? 0 : 1;
  }

  // A DVI link carries no more refreshes than its pixel clock allows (dual link, CVT reduced
  // blanking): asked for more, the emulator refreshes as fast as the link could carry frames.
  void cap_refresh_at_the_link() {
    if (o_.refresh_hz <= 0) return;
    const int w = wall_.framebuffer_width, h = wall_.framebuffer_height;
    const int most = max_refresh_hz(w, h, kDualLinkDviMhz);
    if (o_.refresh_hz <= most) return;
    std::fprintf(stderr,
                 "l2wall: warning: framebuffers of %dx%d at %g Hz need a %.2f MHz pixel clock, "
                 "more than dual-link DVI carries (%g MHz): the emulator refreshes at %d Hz\n",
                 w, h, o_.refresh_hz,
                 dvi_timing(w, h, static_cast<int>(o_.refresh_hz)).pixel_clock_mhz, kDualLinkDviMhz,
                 most);
    o_.refresh_hz = most;
  }

  // Whether a progress line is on stderr (an error then starts a line of its own).
  bool progress_shown() const { return progress_shown_; }

  // After a fault: what the displays show now goes to DIR/fault/. Nullopt if there was
  // nothing; else what is not there (displays lost with a rank of an MPI run), or empty.
  std::optional<std::string> save_displays_after_fault() {
    try {
      const auto dir = std::filesystem::path(o_.out) / "fault";
      std::optional<std::string> saved;
      for (std::size_t i = 0; i < paths_.size(); ++i) {
        if (const auto pictures = paths_[i]->shown()) {
          const auto missing = write_display_pictures(dir, wall_, *pictures, picture_suffix(i));
          saved = missing.empty() ? ""
                                  : fmt::format(" (not display {}: lost with its rank)",
                                                fmt::join(missing, ", "));
        }
      }
      return saved;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "l2wall: could not save the displays: %s\n", e.what());
      return std::nullopt;
    }
  }

  // After a fault, once every process is ended (their logs are complete): report.csv and
  // summary.txt of the frames that reached the displays before it, the summary's first line
  // naming the fault; the summary printed as at a run's end. Nothing when the pipeservers had
  // not started: nothing was measured.
  void write_report_after_fault(const std::string& fault) {
    std::string summary;
    if (pipeservers_started_) {
      try {
        o_.frames = shown_;
        records_.resize(static_cast<std::size_t>(shown_));
        summary = write_report(fault);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "l2wall: could not write the report: %s\n", e.what());
      }
    }
    if (page_) {
      page_->event(shown_ - 1, fault);
      page_->end("ended in a fault: " + fault, summary);
    }
  }

  // Ends every process of the run and reaps it; removes the links a dead pipeserver left. All are
  // asked first, so their grace periods overlap.
  void shut_down() {
    pipeservers_.request_stop();
    for (auto& p : paths_) p->shut_down();
    pipeservers_.shut_down();
  }

 private:
  void check_options() const {
    if (const Status s = run_options_error(o_); !s.ok()) throw std::invalid_argument(s.reason());
    if (const Status s = balance_refusal(o_, wall_, RunPlace::OneMachine); !s.ok())
      throw LayoutError(s.reason());
  }

  // A balanced run: the coordinator, and the DVI path following its layouts.
  void start_balance() {
    if (!run_balance(o_, wall_).balancing()) return;
    const BalanceSpec spec = run_balance(o_, wall_);
    Wall wall = wall_;
    wall.balance = spec;
    balance_ = std::make_unique<LiveBalance>(wall, balance_settings(wall), layout_, o_.frames);
    paths_.front()->follow_layouts(*balance_, pipeservers_);
  }

  // A session run: the coordinator of its windows, which the page moves.
  void start_windows() {
    if (o_.scene != "session") return;
    const auto at = std::find(o_.scene_args.begin(), o_.scene_args.end(), "--session");
    if (at == o_.scene_args.end() || at + 1 == o_.scene_args.end()) return;
    const Session session = load_session(*(at + 1));
    windows_ = std::make_unique<LiveWindows>(session);
    start_session_desktops(session);
  }

  // A session's vnc windows: one connection per desktop, made before any pipeserver starts,
  // as a vnc run's.
  void start_session_desktops(const Session& session) {
    if (std::none_of(session.windows.begin(), session.windows.end(),
                     [](const SessionWindow& w) { return w.source == "vnc"; }))
      return;
    if (balance_)
      throw std::runtime_error(
          "a session's vnc windows are sent for the wall file's tiles: it takes no balancing "
          "(--balance, or the wall file's [balance])");
    try {
      session_desktops_ = std::make_unique<SessionDesktops>(session, layout_, connect_vnc);
    } catch (const DesktopError& e) {
      throw std::runtime_error(e.what());
    }
  }

  void serve_windows() {
    if (windows_) windows_->serve(pipeservers_, session_desktops_.get());
    if (desktop_) desktop_->serve(pipeservers_);
  }

  // A vnc run: the one connection to the desktop's server, made before any pipeserver starts
  // (a server that cannot be reached is one line, not a fault of every pipeserver).
  void start_desktop() {
    if (o_.scene != "vnc") return;
    if (balance_)
      throw std::runtime_error(
          "--scene vnc sends each pipeserver the desktop of the wall's tiles: it takes no "
          "balancing (--balance, or the wall file's [balance])");
    const auto at = std::find(o_.scene_args.begin(), o_.scene_args.end(), "--content");
    if (at == o_.scene_args.end() || at + 1 == o_.scene_args.end()) return;
    try {
      desktop_ =
          std::make_unique<LiveDesktop>(connect_vnc(*(at + 1), o_.vnc_password_file), layout_);
    } catch (const DesktopError& e) {
      throw std::runtime_error(e.what());
    }
  }

  // The lead path first: the DVI path when it runs (its refreshes pace the run), beside it
  // the compositing server, whose frames are taken (and compared) as the lead swaps.
  void make_paths() {
    if (runs_dvi(o_.path)) paths_.push_back(backends_.dvi_path(layout_, o_));
    if (runs_viz(o_.path)) paths_.push_back(backends_.viz_path(viz_launch()));
  }

  PipeserverLaunch launch_pipeservers() const {
    PipeserverLaunch l = pipeserver_launch(o_);
    for (const auto& p : paths_) p->add_pipeserver_args(l);
    l.extra_args = pausable_pipeserver_args(o_);
    l.control = balance_ != nullptr;
    l.windows = windows_ != nullptr || desktop_ != nullptr;  // a vnc run's desktop goes there
    return l;
  }

  VizLaunch viz_launch() const {
    VizLaunch l;
    l.program = o_.vizserver_program;
    l.host = o_.viz_host;
    l.port = o_.viz_port;
    for (const Display& d : wall_.displays) l.display_sizes.emplace_back(d.width, d.height);
    l.pipeservers = static_cast<int>(layout_.pipeservers.size());
    l.frames = o_.frames;
    l.start_timeout = milliseconds(o_.start_timeout_ms);
    l.log = std::filesystem::path(o_.out) / "vizserver.log";
    l.survive_losses = run_balance(o_, wall_).survive_host_loss;
    return l;
  }

  // The lead's pictures are named display-<i>.png, the other path's display-<i>-<label>.png.
  std::string picture_suffix(std::size_t path) const {
    return path == 0 ? std::string() : "-" + paths_[path]->label();
  }

  // --- the frames: the lead path's swaps ---------------------------------------------------

  // A stop signal once a frame is shown ends the frames as q does. Ctrl-C reaches the
  // pipeservers and the compositing server too (one process group): what their end looks
  // like to the run is the signal's effect, not a fault of theirs.
  void run_frames_until_stopped() {
    try {
      run_frames();
    } catch (const RunFault&) {
      if (stop_signal_received() == 0 || shown_ == 0) throw;
      stopped_ = stop_signal_received();
      if (o_.progress) std::fputs("\n", stderr);
    }
  }

  void run_frames() {
    DisplayPath& lead = *paths_.front();
    totals_.latency_measured = lead.refreshed();
    totals_.start = RunClock::now();
    last_swap_ = totals_.start;
    while (shown_ < o_.frames) {
      if (show_ && !keep_showing()) break;
      if (page_ && !follow_page()) break;
      if (o_.window_stdin) take_stdin_windows();
      if (const auto swap = lead.step(shown_, pipeservers_, records_, watch_)) on_swap(*swap);
      check_stall();
    }
  }

  void on_swap(const PathSwap& swap) {
    const auto now = swap.time;
    // Without refreshes the clock starts once every pipeserver has delivered its first frame, as
    // it does after the DVI links carry their first frames.
    if (shown_ == 0 && !swap.refresh) totals_.start = now;
    last_swap_ = now;  // the displays swapped: the other path's frame is waited from here
    while (shown_ <= swap.lowest && shown_ < o_.frames) {
      FrameRecord& r = records_[static_cast<std::size_t>(shown_)];
      r.shown = true;
      r.swap_time = now;
      r.writing_ms = writing_ms_;
      r.paused_ms = paused_ms_;
      if (swap.refresh) {
        r.swap_refresh = *swap.refresh;
        check_latency(r);
      } else {
        r.in_time = now;
      }
      take_from_other_paths(shown_);
      if (saved_.saves(shown_, o_.frames)) save_frame(shown_);
      if (shown_ == o_.noise_after) {
        for (auto& p : paths_) totals_.noise_bytes += p->inject_noise(pipeservers_);
      }
      ++shown_;
    }
    // The stall clock restarts once this swap's work is done: the time spent comparing and
    // keeping pictures, or waiting for the other path's frame, is not a pipeserver's.
    last_swap_ = RunClock::now();
    if (show_ && shown_ > 0) {
      const FrameRecord& r = records_[static_cast<std::size_t>(shown_ - 1)];
      show_->show(shown_ - 1, static_cast<long>(r.swap_refresh) - static_cast<long>(r.in_refresh),
                  *paths_.front()->shown());
    }
    if (page_ && page_->due()) publish_page();
    progress(now);
  }

  void check_latency(const FrameRecord& r) {
    const long latency = static_cast<long>(r.swap_refresh) - static_cast<long>(r.in_refresh);
    // A frame a lost pipeserver never delivered waited until its death was noticed: counted stale.
    if (latency != 1 && balance_ && balance_->stale(shown_)) {
      balance_->note_late(shown_);
      if (page_) page_->event(shown_, "stale: shown late, without a lost pipeserver's part");
      return;
    }
    if (latency != 1) {
      latency_ok_ = false;
      std::fprintf(stderr, "\nl2wall: frame %d: latency %ld refreshes, expected 1\n", shown_,
                   latency);
      if (page_) page_->event(shown_, fmt::format("latency {} refreshes, expected 1", latency));
    }
  }

  // Both paths: the other path's frame too, every one, compared or not — the compositing
  // server waits for us to take its frames before it swaps more.
  void take_from_other_paths(int frame) {
    for (std::size_t i = 1; i < paths_.size(); ++i) {
      if (!o_.compare) {
        paths_[i]->take_frame(frame, watch_);
        continue;
      }
      const DisplayPictures theirs = paths_[i]->frame_pictures(frame, watch_);
      totals_.compared_displays += static_cast<std::uint64_t>(
          compare_paths(frame, wall_, paths_.front()->frame_pictures(frame, watch_), theirs,
                        frame == o_.inject_mismatch, o_.out));
    }
  }

  void save_frame(int frame) {
    const Timed timed(writing_ms_);
    const auto dir = std::filesystem::path(o_.out) / fmt::format("frame-{}", frame);
    // A picture that cannot be written stops the run: the error also says what OUT holds, the
    // pictures of this frame written before it included (each is whole or not there).
    const auto write = [&](const DisplayPictures& pictures, const std::string& suffix) {
      try {
        write_display_pictures(dir, wall_, pictures, suffix);
      } catch (const RunFault&) {
        throw;
      } catch (const std::runtime_error& e) {
        std::vector<std::string> held;
        if (kept_ > 0) held.push_back(fmt::format("the frames kept before frame {}", frame));
        if (const std::string part = pictures_in(dir); !part.empty())
          held.push_back(fmt::format("{} of frame {}", part, frame));
        throw partly_written(e, o_.out, fmt::format("{}", fmt::join(held, ", ")),
                             "no summary.txt or report.csv of this run");
      }
    };
    for (std::size_t i = 0; i < paths_.size(); ++i)
      write(paths_[i]->frame_pictures(frame, watch_), picture_suffix(i));
    ++kept_;
  }

  // --- faults ----------------------------------------------------------------------------

  // A stop signal, a process that ended early, or a path whose process or stream broke: a
  // RunFault naming the cause.
  void check_processes() {
    if (stopped_) return;  // the processes are ending by the signal; the run is over
    check_stop_signal(shown_, displays_showing());
    LivePipeserver* ended = pipeservers_.poll_ended();
    while (ended && survive(*ended)) ended = pipeservers_.poll_ended();
    const bool path_down =
        std::any_of(paths_.begin(), paths_.end(), [](const auto& p) { return p->down(); });
    if (ended || path_down) throw RunFault(blame());
  }

  // --survive-host-loss: the run goes on without a pipeserver that ended, its tiles planned over
  // the others from the next layout on. False when it cannot (no balancing run, not yet running,
  // the last pipeserver) or should not (the pipeserver gave up waiting for READY: an effect whose
  // cause blame() names): the run ends on it as without the option.
  bool survive(LivePipeserver& h) {
    if (!balance_ || !balance_->survives_losses() || !pipeservers_started_) return false;
    if (gave_up_waiting(h)) return false;
    const std::string how = pipeservers_.ended_how(h);
    // Lost while the run starts (before every first frame), it is lost at the run's second 0.
    const double seconds = links_open_ ? ms_between(totals_.start, RunClock::now()) / 1000.0 : 0.0;
    if (!balance_->lose(h.pipeserver, pipeservers_.delivered(h), how, seconds)) return false;
    pipeservers_.lose(h);
    for (auto& p : paths_) p->lose_pipeserver(h.pipeserver);
    std::fprintf(stderr, "%sl2wall: %s; the run goes on without it (--survive-host-loss)\n",
                 progress_shown_ ? "\n" : "", how.c_str());
    if (page_) page_->event(shown_ - 1, how + "; the run goes on without it");
    return true;
  }

  // When one process fails the others lose their connection to it and end too; name the cause.
  // A process killed by a signal is never such an effect. A compositing server that died
  // without saying why is the cause of the pipeservers losing it; one that said why (a
  // pipeserver disconnected) is an effect, its words name the pipeserver. One still running that a
  // pipeserver gave up on hangs: it is named, not the pipeserver.
  std::string blame() {
    for (auto& p : paths_) p->settle(milliseconds(300));
    if (LivePipeserver* killed = pipeservers_.killed_by_signal())
      return pipeservers_.describe_end(*killed, displays_showing());
    for (auto& p : paths_) {
      if (const Status why = p->failure_as_cause(shown_, displays_showing()); !why.ok())
        return why.reason();
    }
    if (LivePipeserver* ended = pipeservers_.poll_ended()) {
      // A pipeserver that gave up waiting (for READY or SWAPPED) is an effect when another, still
      // there, never delivered the frame everyone waits for: that one stopped answering.
      if (gave_up_waiting(*ended)) {
        if (const LivePipeserver* hung = pipeservers_.hung_pipeserver(shown_)) {
          return fmt::format(
              "pipeserver {} ({}) stopped answering{}: it did not deliver frame {}, and "
              "pipeserver {} gave up {} ({}); {}",
              hung->pipeserver, hung->process->place(), PipeserverSet::stopped_note(*hung), shown_,
              ended->pipeserver, waiting_for(*ended), ended->exit->describe(), displays_showing());
        }
      }
      for (auto& p : paths_) {
        if (const Status why = p->hang_behind(*ended, shown_, displays_showing()); !why.ok())
          return why.reason();
      }
      return pipeservers_.describe_end(*ended, displays_showing());
    }
    for (auto& p : paths_) {
      if (const Status why = p->failure(shown_, displays_showing()); !why.ok()) return why.reason();
    }
    return "a process of the run ended";
  }

  static bool gave_up_waiting(const LivePipeserver& h) {
    return h.exit && h.exit->signal == 0 &&
           (h.exit->code == kExitNoReady || h.exit->code == kExitLostCompositingServer);
  }

  // What a pipeserver that gave up was waiting for, by its exit code.
  std::string waiting_for(const LivePipeserver& h) const {
    if (h.exit->code == kExitNoReady) return "waiting for READY";
    const std::string server = server_process();
    return "waiting for SWAPPED from the " + (server.empty() ? std::string("vizserver") : server);
  }

  // How messages name the process a path runs (the compositing server), or empty.
  std::string server_process() const {
    for (const auto& p : paths_) {
      if (std::string name = p->process_name(); !name.empty()) return name;
    }
    return {};
  }

  void check_stall() {
    if (shown_ >= o_.frames) return;  // every frame is on the displays: nothing to wait for
    const auto now = RunClock::now();
    // Before the first swap the pipeservers may still be starting (GL context, first render).
    const int limit_ms = shown_ == 0 ? o_.start_timeout_ms : o_.stall_timeout_ms;
    const double waited_ms = ms_between(last_swap_, now);
    if (waited_ms < limit_ms) return;
    // A pipeserver that has not delivered the frame the displays wait for is the one that hangs; if
    // every pipeserver delivered it, the compositing server did not.
    std::string culprits = pipeservers_.late_pipeservers(shown_);
    if (const std::string server = server_process(); culprits.empty() && !server.empty())
      culprits = "the " + server;
    if (!stall_ends_run(waited_ms, limit_ms, !culprits.empty())) return;
    if (culprits.empty()) {
      throw RunFault(fmt::format(
          "no display swap for {:.0f} ms though every pipeserver delivered frame {}: no process "
          "of the run is late (was the machine too busy?); {}",
          waited_ms, shown_, displays_showing()));
    }
    // What the pipeservers that did deliver are doing: waiting for the swap that cannot come.
    std::string note;
    const auto& all = pipeservers_.all();
    const bool some_delivered = std::any_of(all.begin(), all.end(), [&](const LivePipeserver& h) {
      return pipeservers_.delivered(h) > shown_;
    });
    if (const LivePipeserver* hung =
            some_delivered ? pipeservers_.hung_pipeserver(shown_) : nullptr) {
      note =
          fmt::format("{}; the other pipeservers are waiting for {}",
                      PipeserverSet::stopped_note(*hung), paths_.front()->pipeservers_wait_for());
    }
    throw RunFault(fmt::format("no display swap for {} ms: {} did not deliver frame {}{}; {}",
                               limit_ms, culprits, shown_, note, displays_showing()));
  }

  // What the displays show now, for a fault message. With both paths they can differ by a
  // frame: the emulator swapped frame K while the run waited for the compositing server's K.
  std::string displays_showing() const {
    if (paths_.empty()) return "no frame reached the displays";
    const int frame = paths_.front()->frame_shown();
    const bool same = std::all_of(paths_.begin(), paths_.end(),
                                  [&](const auto& p) { return p->frame_shown() == frame; });
    if (same) {
      if (frame < 0) return "no frame reached the displays";  // not "frame -1"
      return fmt::format("the displays keep frame {}", frame);
    }
    std::string each;
    for (const auto& p : paths_)
      each +=
          fmt::format("{}frame {} ({})", each.empty() ? "" : " and ", p->frame_shown(), p->name());
    return "the displays keep " + each;
  }

  // --- --show ------------------------------------------------------------------------------

  // --show: the keys, and a pause that holds the run (nothing taken in, no READY sent, the
  // pipeservers wait) while still watching the pipeservers. False once the user quit and a frame is
  // shown.
  bool keep_showing() {
    const LiveShow::Keys k = show_->keys([this] {
      check_processes();
      pipeservers_.serve_channels();
    });
    paused_ms_ += static_cast<double>(k.paused.count());  // the pipeservers wait too: not fps
    last_swap_ += k.paused;                               // nor a stall
    return !(k.quit && shown_ > 0);
  }

  // q / Esc: the frames shown so far are the run, as if --frames had said so. The pipeservers,
  // still rendering the rest, are stopped; --keep last saves this frame.
  void end_at_quit() {
    const bool saved = saved_.saves(shown_ - 1, o_.frames);
    o_.frames = shown_;
    records_.resize(static_cast<std::size_t>(shown_));
    if (!saved && saved_.saves(shown_ - 1, o_.frames)) save_frame(shown_ - 1);
    shut_down();
  }

  // --- --http: the control page ----------------------------------------------------------

  void watch_pipeservers_on_the_page() {
    std::vector<std::string> logs, places;
    for (const LivePipeserver& h : pipeservers_.all()) {
      logs.push_back(h.report_path);
      places.push_back(h.process ? h.process->place() : std::string());
    }
    page_->watch_pipeservers(logs, places);
  }

  // The page's requests, at a frame boundary; a pause holds the run here (nothing taken in, no
  // READY sent, the pipeservers wait) while still watching the pipeservers. False once the page
  // asked to stop and a frame is shown.
  bool follow_page() {
    take_page_requests();
    if (steering_.paused) {
      const auto since = RunClock::now();
      while (steering_.paused && !steering_.stop) {
        std::this_thread::sleep_for(milliseconds(10));
        check_processes();
        pipeservers_.serve_channels();
        take_page_requests();
        if (page_->due()) publish_page();
      }
      const auto paused = std::chrono::duration_cast<milliseconds>(RunClock::now() - since);
      paused_ms_ += static_cast<double>(paused.count());  // the pipeservers wait too: not fps
      last_swap_ += paused;                               // nor a stall
    }
    if (page_->due()) publish_page();
    return !(steering_.stop && shown_ > 0);
  }

  void take_page_requests() {
    const int frame = shown_ - 1;
    for (const ControlRequest& r : page_->requests()) {
      switch (r.action) {
        case ControlAction::Pause:
          if (!steering_.paused) ++steering_.pauses;
          steering_.paused = true;
          page_->event(frame, "paused: READY held back, the pipeservers wait");
          break;
        case ControlAction::Resume:
          steering_.paused = false;
          page_->event(frame, "resumed");
          break;
        case ControlAction::Save:
          save_from_page(frame);
          break;
        case ControlAction::Stop:
          if (!backends_.stops_pipeservers_early()) {
            page_->event(frame,
                         "not stopped: the pipeserver ranks cannot be ended early under --mpi; "
                         "Ctrl-C on mpirun ends the run");
            break;
          }
          steering_.stop = true;
          steering_.stopped_at = frame;
          page_->event(frame, "stopped from the control page");
          break;
        case ControlAction::Balance:
          switch_balance(r.argument, frame);
          break;
        case ControlAction::Window:
          window_command(r.argument, frame);
          break;
      }
    }
  }

  void save_from_page(int frame) {
    if (frame < 0) return page_->event(frame, "not saved: no frame on the displays yet");
    save_frame(frame);
    ++steering_.saves;
    page_->event(
        frame,
        fmt::format("saved the displays to {}",
                    (std::filesystem::path(o_.out) / fmt::format("frame-{}", frame)).string()));
  }

  // Taken from the next frame whose windows are decided: every pipeserver moves it then. The
  // page's events say what was done, and without a page stderr does.
  void window_command(const std::string& command, int frame) {
    std::string why = "this run shows no session (start it with --scene session)";
    if (windows_ && !windows_moving_here())
      why = "windows do not move under --mpi";
    else if (windows_)
      why = windows_->command(command);
    const std::string said =
        why.empty() ? "window: " + command + " from the next frame" : "window not changed: " + why;
    if (page_) return page_->event(frame, said);
    std::fprintf(stderr, "l2wall: %s\n", said.c_str());
  }

  // Whether the pipeservers take WINDOWS lines (over MPI too, --mpi-windows): all of a session's.
  bool windows_moving_here() const {
    return !pipeservers_.all().empty() && pipeservers_.all().front().windows;
  }

  // --window-stdin: the whole lines waiting on stdin, without waiting for more.
  void take_stdin_windows() {
    for (const std::string& line : stdin_lines_.take()) window_command(line, shown_ - 1);
  }

  void switch_balance(const std::string& mode, int frame) {
    std::string why = "this run does not balance (start it with --balance or [balance])";
    if (balance_ && balance_->switch_mode(mode, frame, why))
      return page_->event(frame, "balance mode: " + mode + " from the next layout");
    page_->event(frame, "balance not switched: " + why);
  }

  void publish_page() {
    PageMoment m;
    m.frame = shown_ - 1;
    const double seconds = (ms_between(totals_.start, RunClock::now()) - paused_ms_) / 1000.0;
    m.fps = shown_ > 0 && seconds > 0 ? shown_ / seconds : 0.0;
    if (shown_ > 0 && totals_.latency_measured) {
      const FrameRecord& r = records_[static_cast<std::size_t>(shown_ - 1)];
      m.latency_frames = static_cast<long>(r.swap_refresh) - static_cast<long>(r.in_refresh);
    }
    m.paused = steering_.paused;
    m.tiles = balance_ ? page_tiles(balance_->layout_for(shown_ - 1)) : page_tiles(layout_);
    for (const LivePipeserver& h : pipeservers_.all()) m.lost.push_back(h.lost);
    if (runs_dvi(o_.path)) {
      for (int k = std::max(0, shown_ - 60); k < shown_; ++k)
        m.recent_route.push_back(records_[static_cast<std::size_t>(k)].route_ms);
      m.refresh_hz = o_.refresh_hz;
    }
    if (balance_) m.balance_mode = balance_->mode();
    if (windows_) {
      for (const WindowPlace& w : windows_->shown_at(shown_ - 1)) {
        const Rect& r = w.on_canvas;
        m.windows.push_back({w.id, windows_->source_of(w.id), r.x, r.y, r.w, r.h});
      }
      m.windows_movable = windows_moving_here();
    }
    // Nobody watching: no pictures gathered (under --mpi each is a fetch from a column rank).
    if (shown_ == 0 || !page_->watched()) return page_->publish(m, nullptr);
    const DisplayPictures pictures = paths_.front()->frame_pictures(shown_ - 1, watch_);
    page_->publish(m, &pictures);
  }

  // --- output ------------------------------------------------------------------------------

  void progress(RunClock::time_point now) {
    if (!o_.progress) return;
    progress_shown_ = true;
    const double s = ms_between(totals_.start, now) / 1000.0;
    // Ended by erase-to-end-of-line (only ever drawn on a terminal): it overwrites the longer
    // line of the wait for the first frames.
    std::fprintf(stderr, "\rl2wall: frame %d/%d on the displays, %.1f fps\033[K", shown_, o_.frames,
                 s > 0 ? shown_ / s : 0.0);
    std::fflush(stderr);
  }

  // Before the first frames, which wait for each pipeserver to read its model or picture (a
  // large one takes seconds): a line a second, so a slow start is seen as one, not a hang.
  void waiting_progress() {
    if (!o_.progress) return;
    const auto now = RunClock::now();
    if (!waiting_since_) waiting_since_ = now;
    const auto seconds = static_cast<int>(ms_between(*waiting_since_, now) / 1000.0);
    if (seconds < 1 || seconds == waiting_shown_) return;
    waiting_shown_ = seconds;
    progress_shown_ = true;
    std::fprintf(stderr,
                 "\rl2wall: waiting for the pipeservers' first frames, %d s (each reads its "
                 "model or picture first; --start-timeout %d ms)",
                 seconds, o_.start_timeout_ms);
    std::fflush(stderr);
  }

  // `fault`: the fault that ended the run at frame shown_, or empty.
  // Returns the summary.
  std::string write_report(const std::string& fault) {
    for (const auto& p : paths_) p->add_totals(totals_);
    totals_.lost.clear();
    for (const LivePipeserver& h : pipeservers_.all()) totals_.lost.push_back(h.lost);
    std::vector<std::string> pipeserver_logs;
    for (const LivePipeserver& h : pipeservers_.all()) pipeserver_logs.push_back(h.report_path);
    const std::string extra = (show_ ? show_->summary(shown_) : std::string()) +
                              (page_ ? steering_.summary() : std::string()) +
                              (balance_ ? balance_->summary() : std::string()) +
                              (windows_ ? windows_->summary() : std::string()) +
                              (desktop_ ? desktop_->summary() : std::string()) +
                              (session_desktops_ ? session_desktops_->summary() : std::string());
    const RunReportTexts report =
        run_report(o_, wall_, pipeserver_logs, records_, totals_, extra, fault);
    std::vector<std::pair<std::string, std::string>> files;
    if (balance_) files.emplace_back("layouts.txt", balance_->layouts());
    if (windows_) files.emplace_back("windows.txt", windows_->windows());
    files.emplace_back("report.csv", report.csv);
    files.emplace_back("summary.txt", report.summary);
    write_report_files(files);
    if (o_.progress && fault.empty()) std::fputs("\n", stderr);  // a fault's line ended it
    std::fputs(report.summary.c_str(), stdout);
    return report.summary;
  }

  // In order; one that cannot be written ends the run, saying what OUT holds and what not.
  void write_report_files(const std::vector<std::pair<std::string, std::string>>& files) const {
    std::vector<std::string> held;
    if (kept_ > 0) held.emplace_back("the frames kept");
    for (std::size_t i = 0; i < files.size(); ++i) {
      try {
        write_whole_file(std::filesystem::path(o_.out) / files[i].first, files[i].second);
      } catch (const std::runtime_error& e) {
        std::vector<std::string> missing;
        for (std::size_t j = i; j < files.size(); ++j) missing.push_back(files[j].first);
        throw partly_written(e, o_.out, fmt::format("{}", fmt::join(held, ", ")),
                             fmt::format("no {} of this run", fmt::join(missing, " or ")));
      }
      held.push_back(files[i].first);
    }
  }

  RunOptions o_;
  const RunBackends& backends_;
  SavedFrames saved_;
  Wall wall_;
  TileLayout layout_;
  std::unique_ptr<LiveShow> show_;                     // --show: the displays on screen, keys
  std::unique_ptr<LivePage> page_;                     // --http: the control page
  PageSteering steering_;                              // what the page asked for
  std::vector<std::unique_ptr<DisplayPath>> paths_;    // the lead first (--path)
  std::unique_ptr<LiveBalance> balance_;               // a balanced run's coordinator
  std::unique_ptr<LiveWindows> windows_;               // a session run's windows
  std::unique_ptr<LiveDesktop> desktop_;               // a vnc run's desktop
  std::unique_ptr<SessionDesktops> session_desktops_;  // a session's vnc windows' desktops
  LineReader stdin_lines_{STDIN_FILENO};               // --window-stdin
  PipeserverSet pipeservers_;  // after paths_: destroyed first, so pipeservers end before the
                               // compositing server
  std::vector<FrameRecord> records_;
  RunTotals totals_;
  // A session's windows and a vnc run's desktop are served with the processes: WANT comes
  // before each READY wait.
  const RunWatch watch_{[this] {
                          check_processes();
                          serve_windows();
                          if (!links_open_) waiting_progress();
                        },
                        [this] {
                          check_processes();
                          check_stall();
                          pipeservers_.serve_channels();
                          serve_windows();
                        }};
  bool progress_shown_ = false;
  std::optional<RunClock::time_point> waiting_since_;  // the wait for the first frames
  int waiting_shown_ = 0;                              // its seconds last shown
  bool pipeservers_started_ = false;
  bool links_open_ = false;  // every pipeserver delivered its first frame
  int shown_ = 0;            // frames 0 .. shown_-1 have reached every display (and were checked)
  bool latency_ok_ = true;
  int stopped_ = 0;        // the stop signal that ended the frames, or 0
  double writing_ms_ = 0;  // spent writing saved pictures during the run
  int kept_ = 0;           // frames whose pictures were all written (--keep)
  double paused_ms_ = 0;   // spent paused by the --show keys
  RunClock::time_point last_swap_{};
};

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
    std::fprintf(stderr, "l2wall: %s\n", e.what());
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
