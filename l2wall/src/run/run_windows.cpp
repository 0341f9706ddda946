#include "run_windows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "desktops/desktop_source.hpp"
#include "tilelayout/session_file.hpp"

namespace l2 {

void RunWindows::start(const RunOptions& o, const TileLayout& layout, bool balanced) {
  canvas_width_ = layout.wall.canvas_width;
  canvas_height_ = layout.wall.canvas_height;
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
  if (session.shares == 0 && std::none_of(session.windows.begin(), session.windows.end(),
                                          [](const SessionWindow& w) { return w.source == "vnc"; }))
    return;
  if (balanced)
    throw std::runtime_error(
        "a session's vnc windows and shares are sent for the wall file's tiles: it takes no "
        "balancing (--balance, or the wall file's [balance])");
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
  if (!no.why.empty()) return {status, "window not changed: " + no.why};
  if (command.rfind("close ", 0) == 0) closed(std::atoi(command.c_str() + 6));
  return {200, "window: " + command + " from the next frame"};
}

void RunWindows::closed(int id) {
  if (!session_desktops_ || !session_desktops_->shares().close(id)) return;
  if (share_inbox_) share_inbox_->close(id);
}

int RunWindows::share_slots() const {
  return session_desktops_ ? session_desktops_->shares().slots() : 0;
}

ControlDecision RunWindows::share(const std::string& request,
                                  const std::shared_ptr<ShareInbox>& inbox,
                                  const PipeserverSet& pipeservers) {
  if (!windows_)
    return {409, "not shared: this run shows no session (start it with --scene session)"};
  if (!moving_here(pipeservers)) return {409, "not shared: windows do not change under --mpi"};
  int w = 0, h = 0, cx = -1, cy = -1, name_at = 0;
  if (std::sscanf(request.c_str(), "%d %d %d %d %n", &w, &h, &cx, &cy, &name_at) != 4 ||
      name_at == 0 || w < 1 || h < 1 || w > kMaxShareWidth || h > kMaxShareHeight)
    return {400, fmt::format("not shared: expected W H CX CY NAME, W 1..{} and H 1..{}",
                             kMaxShareWidth, kMaxShareHeight)};
  const std::string name = request.substr(static_cast<std::size_t>(name_at));
  if (share_slots() == 0)
    return {409,
            "not shared: the session takes no shares (give it shares = N, "
            "docs/session-file.md)"};
  share_inbox_ = inbox;
  const Rect place = share_place(canvas_width_, canvas_height_, w, h, cx, cy);
  // The slot's desktop starts with the frame the window is first shown in.
  const int from = windows_->next_frame();
  SessionShares& shares = session_desktops_->shares();
  const Result<int> window = shares.free_window();
  if (!window.ok()) return {409, "not shared: " + window.reason()};
  shares.open(*window, share_source(inbox, *window, w, h), name, from);
  windows_->open(*window, place);
  inbox->open(*window, name, w, h);
  return {200, fmt::format("sharing {} as window {} ({}x{}) at {},{} {}x{}", name, *window, w, h,
                           place.x, place.y, place.w, place.h)};
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
