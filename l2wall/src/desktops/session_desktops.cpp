#include "session_desktops.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "l2wall/run_fault.hpp"

namespace l2 {

SessionDesktops::SessionDesktops(const Session& session, const TileLayout& layout,
                                 const Connect& connect)
    : shares_(session, layout) {
  for (const PipeserverPlan& p : layout.pipeservers) {
    std::vector<Rect>& rects = tiles_.emplace_back();
    for (const PackedTile& t : p.tiles) rects.push_back(t.tile.on_canvas);
  }
  // Grouped as the pipeservers' session scene groups them (scene_session.cpp).
  for (const SessionWindow& w : session.windows) {
    if (w.source != "vnc") continue;
    const std::string address = w.content.string(), password = w.password_file.string();
    auto at = std::find_if(desktops_.begin(), desktops_.end(), [&](const Desktop& d) {
      return d.address == address && d.password_file == password;
    });
    if (at == desktops_.end()) {
      desktops_.push_back({address, password, w.id, {}, nullptr});
      at = desktops_.end() - 1;
    }
    at->windows.push_back({w.id, parse_source_fit(w.fit).value_or(SourceFit::Fit)});
  }
  for (Desktop& d : desktops_) {
    try {
      d.live = std::make_unique<LiveDesktop>(connect(d.address, d.password_file), layout);
    } catch (const DesktopError& e) {
      throw DesktopError(fmt::format("window {}: {}", d.first_window, e.what()));
    }
  }
}

void SessionDesktops::take_updates() {
  for (Desktop& d : desktops_) {
    try {
      d.live->take_updates();
    } catch (const RunFault& e) {
      throw RunFault(fmt::format("window {}: {}", d.first_window, e.what()));
    }
  }
  try {
    shares_.take_updates();
  } catch (const DesktopError& e) {
    throw RunFault(e.what());
  }
}

std::vector<std::string> SessionDesktops::answer(int pipeserver, int frame,
                                                 const std::vector<WindowPlace>& shown) {
  std::vector<std::string> lines;
  const std::vector<Rect>& tiles = tiles_.at(static_cast<std::size_t>(pipeserver));
  for (Desktop& d : desktops_) {
    const std::vector<std::string> part =
        d.live->answer(pipeserver, frame,
                       desktop_regions(tiles, shown, d.windows, d.live->width(), d.live->height()));
    lines.insert(lines.end(), part.begin(), part.end());
  }
  const std::vector<std::string> shared = shares_.answer(pipeserver, frame, shown);
  lines.insert(lines.end(), shared.begin(), shared.end());
  return lines;
}

std::string SessionDesktops::summary() const {
  std::string out;
  for (const Desktop& d : desktops_)
    out += fmt::format("window {}: {}", d.first_window, d.live->summary());
  return out + shares_.summary();
}

}  // namespace l2
