#include "page_steering.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <thread>
#include <vector>

#include "tilelayout/wall.hpp"

namespace l2 {

void PageSteering::watch_pipeservers() {
  if (!core_.page) return;
  std::vector<std::string> logs, places;
  for (const LivePipeserver& h : core_.pipeservers.all()) {
    logs.push_back(h.report_path);
    places.push_back(h.process ? h.process->place() : std::string());
  }
  core_.page->watch_pipeservers(logs, places);
}

bool PageSteering::follow() {
  if (!core_.page) return true;
  take_requests();
  if (paused_) hold_while_paused();
  if (core_.page->due()) publish();
  return !(stop_ && core_.frames.shown > 0);
}

// While still watching the pipeservers and the page.
void PageSteering::hold_while_paused() {
  const auto since = RunClock::now();
  while (paused_ && !stop_) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    watchdog_.check_processes();
    core_.pipeservers.serve_channels();
    take_requests();
    if (core_.page->due()) publish();
  }
  const auto paused =
      std::chrono::duration_cast<std::chrono::milliseconds>(RunClock::now() - since);
  core_.frames.paused_ms += static_cast<double>(paused.count());  // the pipeservers wait too
  core_.frames.last_swap += paused;                               // nor a stall
}

void PageSteering::after_swap() {
  if (core_.page && core_.page->due()) publish();
}

void PageSteering::take_requests() {
  const int frame = core_.frames.shown - 1;
  for (const ControlRequest& r : core_.page->requests())
    core_.page->decide(frame, r, take_request(r, frame));
}

// What was done, or why not with the status a refusal answers: 400 for a request the run cannot
// read, 404 for a window it does not have, 409 for one this run cannot do now.
ControlDecision PageSteering::take_request(const ControlRequest& r, int frame) {
  switch (r.action) {
    case ControlAction::Pause:
      if (!paused_) ++pauses_;
      paused_ = true;
      return {200, "paused: READY held back, the pipeservers wait"};
    case ControlAction::Resume:
      paused_ = false;
      return {200, "resumed"};
    case ControlAction::Save:
      return save(frame);
    case ControlAction::Stop:
      return stop(frame);
    case ControlAction::Balance:
      return switch_balance(r.argument, frame);
    case ControlAction::Window:
      return windows_.command(r.argument, core_.pipeservers);
    case ControlAction::Share:
      return windows_.share(r.argument, core_.page->shares(), core_.pipeservers);
  }
  return {400, "unknown request"};
}

ControlDecision PageSteering::stop(int frame) {
  if (!stoppable_) {
    return {409,
            "not stopped: the pipeserver ranks cannot be ended early under --mpi; Ctrl-C on "
            "mpirun ends the run"};
  }
  stop_ = true;
  stopped_at_ = frame;
  return {200, "stopped from the control page"};
}

ControlDecision PageSteering::save(int frame) {
  if (frame < 0) return {409, "not saved: no frame on the displays yet"};
  writer_.save_frame(frame);
  ++saves_;
  const auto dir = std::filesystem::path(core_.options.out) / fmt::format("frame-{}", frame);
  return {200, fmt::format("saved the displays to {}", dir.string())};
}

ControlDecision PageSteering::switch_balance(const std::string& mode, int frame) {
  if (!core_.balance)
    return {409,
            "balance not switched: this run does not balance (start it with --balance or "
            "[balance])"};
  std::string why;
  if (core_.balance->switch_mode(mode, frame, why))
    return {200, "balance mode: " + mode + " from the next layout"};
  // A mode it knows that this wall cannot be cut by is the run's refusal, not a misspelling.
  const bool known = std::find(std::begin(kBalanceModeNames), std::end(kBalanceModeNames), mode) !=
                     std::end(kBalanceModeNames);
  return {known ? 409 : 400, "balance not switched: " + why};
}

void PageSteering::publish() {
  const PageMoment m = moment();
  const int shown = core_.frames.shown;
  // Nobody watching: no pictures gathered (under --mpi each is a fetch from a column rank).
  if (shown == 0 || !core_.page->watched()) return core_.page->publish(m, nullptr);
  const DisplayPictures pictures = core_.paths.front()->frame_pictures(shown - 1, watch_);
  core_.page->publish(m, &pictures);
}

PageMoment PageSteering::moment() const {
  const FrameLedger& f = core_.frames;
  PageMoment m;
  m.frame = f.shown - 1;
  const double seconds = (ms_between(f.totals.start, RunClock::now()) - f.paused_ms) / 1000.0;
  m.fps = f.shown > 0 && seconds > 0 ? f.shown / seconds : 0.0;
  if (f.shown > 0 && f.totals.latency_measured) {
    const FrameRecord& r = f.records[static_cast<std::size_t>(f.shown - 1)];
    m.latency_frames = static_cast<long>(r.swap_refresh) - static_cast<long>(r.in_refresh);
  }
  m.paused = paused_;
  m.tiles =
      core_.balance ? page_tiles(core_.balance->layout_for(f.shown - 1)) : page_tiles(core_.layout);
  for (const LivePipeserver& h : core_.pipeservers.all()) m.lost.push_back(h.lost);
  if (runs_dvi(core_.options.path)) {
    for (int k = std::max(0, f.shown - 60); k < f.shown; ++k)
      m.recent_route.push_back(f.records[static_cast<std::size_t>(k)].route_ms);
    m.refresh_hz = core_.options.refresh_hz;
  }
  if (core_.balance) m.balance_mode = core_.balance->mode();
  if (windows_.session()) {
    m.windows = windows_.page_windows(f.shown - 1);
    m.windows_movable = RunWindows::moving_here(core_.pipeservers);
    m.share_slots = windows_.share_slots();
  }
  return m;
}

std::string PageSteering::summary() const {
  if (!core_.page) return {};
  const auto count = [](int n, const char* what) {
    return fmt::format("{} {}{}", n, what, n == 1 ? "" : "s");
  };
  std::string line = "control page: " + count(pauses_, "pause") + ", " + count(saves_, "save");
  if (stop_) line += fmt::format(", stopped from the page at frame {}", stopped_at_);
  return line + "\n";
}

void PageSteering::end(const std::string& how, const std::string& summary) {
  if (core_.page) core_.page->end(how, summary);
}

}  // namespace l2
