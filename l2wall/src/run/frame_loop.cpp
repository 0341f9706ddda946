#include "frame_loop.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "l2wall/run_fault.hpp"
#include "l2wall/stop_signal.hpp"

namespace l2 {

void FrameLoop::open_show() {
  if (!core_.options.show.empty()) show_ = std::make_unique<LiveShow>(core_.options, core_.wall);
}

// Ctrl-C reaches the pipeservers and the compositing server too (one process group): what their
// end looks like to the run is the signal's effect, not a fault of theirs.
void FrameLoop::run_until_stopped() {
  try {
    run_frames();
  } catch (const RunFault&) {
    if (stop_signal_received() == 0 || core_.frames.shown == 0) throw;
    core_.frames.stopped = stop_signal_received();
    if (core_.options.progress) std::fputs("\n", stderr);
  }
}

void FrameLoop::run_frames() {
  FrameLedger& f = core_.frames;
  DisplayPath& lead = core_.lead();
  f.totals.latency_measured = lead.refreshed();
  f.totals.start = RunClock::now();
  f.last_swap = f.totals.start;
  while (f.shown < core_.options.frames) {
    if (show_ && !keep_showing()) break;
    if (!parts_.steering.follow()) break;
    if (core_.options.window_stdin) take_stdin_windows();
    take_touch_windows();
    if (const auto swap = lead.step(f.shown, core_.pipeservers, f.records, watch_)) on_swap(*swap);
    parts_.watchdog.check_stall();
  }
}

void FrameLoop::on_swap(const PathSwap& swap) {
  FrameLedger& f = core_.frames;
  // Without refreshes the clock starts once every pipeserver has delivered its first frame, as it
  // does after the DVI links carry their first frames.
  if (f.shown == 0 && !swap.refresh) f.totals.start = swap.time;
  f.last_swap = swap.time;  // the displays swapped: the other path's frame is waited from here
  while (f.shown <= swap.lowest && f.shown < core_.options.frames) {
    record_frame(swap);
    ++f.shown;
  }
  // The stall clock restarts once this swap's work is done: the time spent comparing and keeping
  // pictures, or waiting for the other path's frame, is not a pipeserver's.
  f.last_swap = RunClock::now();
  show_last_frame();
  parts_.steering.after_swap();
  parts_.progress.frames(swap.time);
}

// Frame `shown`, completed by `swap`: its record, its checks, its pictures.
void FrameLoop::record_frame(const PathSwap& swap) {
  FrameLedger& f = core_.frames;
  const int frame = f.shown;
  FrameRecord& r = f.records[static_cast<std::size_t>(frame)];
  r.shown = true;
  r.swap_time = swap.time;
  r.writing_ms = f.writing_ms;
  r.paused_ms = f.paused_ms;
  if (swap.refresh) {
    r.swap_refresh = *swap.refresh;
    check_latency(r);
  } else {
    r.in_time = swap.time;
  }
  take_from_other_paths(frame);
  if (core_.saved.saves(frame, core_.options.frames)) parts_.writer.save_frame(frame);
  if (frame == core_.options.noise_after) {
    for (auto& p : core_.paths) f.totals.noise_bytes += p->inject_noise(core_.pipeservers);
  }
}

void FrameLoop::check_latency(const FrameRecord& r) {
  FrameLedger& f = core_.frames;
  LivePage* page = core_.page.get();
  const long latency = static_cast<long>(r.swap_refresh) - static_cast<long>(r.in_refresh);
  // A frame a lost pipeserver never delivered waited until its death was noticed: counted stale.
  if (latency != 1 && core_.balance && core_.balance->stale(f.shown)) {
    core_.balance->note_late(f.shown);
    if (page) page->event(f.shown, "stale: shown late, without a lost pipeserver's part");
    return;
  }
  if (latency != 1) {
    f.latency_ok = false;
    std::fprintf(stderr, "\nl2wall: frame %d: latency %ld refreshes, expected 1\n", f.shown,
                 latency);
    if (page) page->event(f.shown, fmt::format("latency {} refreshes, expected 1", latency));
  }
}

// Both paths: the other path's frame too, every one, compared or not — the compositing server
// waits for us to take its frames before it swaps more.
void FrameLoop::take_from_other_paths(int frame) {
  const RunOptions& o = core_.options;
  for (std::size_t i = 1; i < core_.paths.size(); ++i) {
    if (!o.compare) {
      core_.paths[i]->take_frame(frame, watch_);
      continue;
    }
    const DisplayPictures theirs = core_.paths[i]->frame_pictures(frame, watch_);
    core_.frames.totals.compared_displays += static_cast<std::uint64_t>(
        compare_paths(frame, core_.wall, core_.lead().frame_pictures(frame, watch_), theirs,
                      frame == o.inject_mismatch, o.out));
  }
}

void FrameLoop::show_last_frame() {
  const FrameLedger& f = core_.frames;
  if (!show_ || f.shown == 0) return;
  const FrameRecord& r = f.records[static_cast<std::size_t>(f.shown - 1)];
  show_->show(f.shown - 1, static_cast<long>(r.swap_refresh) - static_cast<long>(r.in_refresh),
              *core_.lead().shown());
}

// --show: the keys, and a pause that holds the run (nothing taken in, no READY sent, the
// pipeservers wait) while still watching the pipeservers. False once the user quit and a frame
// is shown.
bool FrameLoop::keep_showing() {
  const LiveShow::Keys k = show_->keys([this] {
    parts_.watchdog.check_processes();
    core_.pipeservers.serve_channels();
  });
  core_.frames.paused_ms += static_cast<double>(k.paused.count());  // the pipeservers wait too
  core_.frames.last_swap += k.paused;                               // nor a stall
  return !(k.quit && core_.frames.shown > 0);
}

void FrameLoop::take_stdin_windows() {
  for (const std::string& line : parts_.windows.stdin_commands()) take_window_command(line, "");
}

// --tuio: the gestures' commands, said as --window-stdin's are, after "touch: ".
void FrameLoop::take_touch_windows() {
  for (const std::string& line : parts_.touch.commands(parts_.windows, core_.frames.shown - 1))
    take_window_command(line, "touch: ");
}

// What was taken or why not goes to the page's events, or without a page to stderr.
void FrameLoop::take_window_command(const std::string& line, const char* from) {
  const std::string said = from + parts_.windows.command(line, core_.pipeservers).text;
  if (core_.page) {
    core_.page->event(core_.frames.shown - 1, said);
  } else {
    std::fprintf(stderr, "l2wall: %s\n", said.c_str());
  }
}

void FrameLoop::cut_at_shown() {
  FrameLedger& f = core_.frames;
  const bool saved = core_.saved.saves(f.shown - 1, core_.options.frames);
  core_.options.frames = f.shown;
  f.records.resize(static_cast<std::size_t>(f.shown));
  if (!saved && core_.saved.saves(f.shown - 1, core_.options.frames))
    parts_.writer.save_frame(f.shown - 1);
}

std::string FrameLoop::show_summary() const {
  return show_ ? show_->summary(core_.frames.shown) : std::string();
}

}  // namespace l2
