#include "run_windows.hpp"

#include <algorithm>
#include <stdexcept>

#include "desktops/desktop_source.hpp"
#include "tilelayout/session_file.hpp"

namespace l2 {

void RunWindows::start(const RunOptions& o, const TileLayout& layout, bool balanced) {
  start_windows(o, layout, balanced);
  start_desktop(o, layout, balanced);
}

// A session run: the coordinator of its windows, which the page moves.
void RunWindows::start_windows(const RunOptions& o, const TileLayout& layout, bool balanced) {
  if (o.scene != "session") return;
  const auto at = std::find(o.scene_args.begin(), o.scene_args.end(), "--session");
  if (at == o.scene_args.end() || at + 1 == o.scene_args.end()) return;
  const Session session = load_session(*(at + 1));
  windows_ = std::make_unique<LiveWindows>(session);
  start_session_desktops(session, layout, balanced);
}

// A session's vnc windows: one connection per desktop, made before any pipeserver starts, as a
// vnc run's.
void RunWindows::start_session_desktops(const Session& session, const TileLayout& layout,
                                        bool balanced) {
  if (std::none_of(session.windows.begin(), session.windows.end(),
                   [](const SessionWindow& w) { return w.source == "vnc"; }))
    return;
  if (balanced)
    throw std::runtime_error(
        "a session's vnc windows are sent for the wall file's tiles: it takes no balancing "
        "(--balance, or the wall file's [balance])");
  try {
    session_desktops_ = std::make_unique<SessionDesktops>(session, layout, connect_vnc);
  } catch (const DesktopError& e) {
    throw std::runtime_error(e.what());
  }
}

// A vnc run: the one connection to the desktop's server, made before any pipeserver starts (a
// server that cannot be reached is one line, not a fault of every pipeserver).
void RunWindows::start_desktop(const RunOptions& o, const TileLayout& layout, bool balanced) {
  if (o.scene != "vnc") return;
  if (balanced)
    throw std::runtime_error(
        "--scene vnc sends each pipeserver the desktop of the wall's tiles: it takes no "
        "balancing (--balance, or the wall file's [balance])");
  const auto at = std::find(o.scene_args.begin(), o.scene_args.end(), "--content");
  if (at == o.scene_args.end() || at + 1 == o.scene_args.end()) return;
  try {
    desktop_ = std::make_unique<LiveDesktop>(connect_vnc(*(at + 1), o.vnc_password_file), layout);
  } catch (const DesktopError& e) {
    throw std::runtime_error(e.what());
  }
}

void RunWindows::serve(PipeserverSet& pipeservers) {
  if (windows_) windows_->serve(pipeservers, session_desktops_.get());
  if (desktop_) desktop_->serve(pipeservers);
}

ControlDecision RunWindows::command(const std::string& command, const PipeserverSet& pipeservers) {
  LiveWindows::Refusal no{"this run shows no session (start it with --scene session)"};
  int status = 409;
  if (windows_ && !moving_here(pipeservers)) {
    no.why = "windows do not move under --mpi";
  } else if (windows_) {
    no = windows_->command(command);
    status = no.no_such_window ? 404 : 400;
  }
  if (no.why.empty()) return {200, "window: " + command + " from the next frame"};
  return {status, "window not changed: " + no.why};
}

bool RunWindows::moving_here(const PipeserverSet& pipeservers) {
  return !pipeservers.all().empty() && pipeservers.all().front().windows;
}

std::vector<WindowPlace> RunWindows::shown_at(int frame) const {
  return windows_ ? windows_->shown_at(frame) : std::vector<WindowPlace>();
}

std::vector<PageWindow> RunWindows::page_windows(int frame) const {
  std::vector<PageWindow> page;
  for (const WindowPlace& w : shown_at(frame)) {
    const Rect& r = w.on_canvas;
    page.push_back({w.id, windows_->source_of(w.id), r.x, r.y, r.w, r.h});
  }
  return page;
}

std::string RunWindows::summary() const {
  return (windows_ ? windows_->summary() : std::string()) +
         (desktop_ ? desktop_->summary() : std::string()) +
         (session_desktops_ ? session_desktops_->summary() : std::string());
}

std::vector<std::pair<std::string, std::string>> RunWindows::files() const {
  if (!windows_) return {};
  return {{"windows.txt", windows_->windows()}};
}

}  // namespace l2
