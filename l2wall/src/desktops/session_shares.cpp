#include "session_shares.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "desktop_regions.hpp"

namespace l2 {

Rect share_place(int canvas_w, int canvas_h, int share_w, int share_h, int cx, int cy) {
  // The largest scale that keeps the window within half the canvas each way and the share's
  // own size: a screen shared onto a wall is one window among others, not the wall.
  const double scale = std::min({1.0, canvas_w / 2.0 / share_w, canvas_h / 2.0 / share_h});
  Rect r;
  r.w = std::max(1, static_cast<int>(share_w * scale));
  r.h = std::max(1, static_cast<int>(share_h * scale));
  r.x = (cx < 0 || cy < 0 ? canvas_w / 2 : cx) - r.w / 2;
  r.y = (cx < 0 || cy < 0 ? canvas_h / 2 : cy) - r.h / 2;
  return r;
}

SessionShares::SessionShares(const Session& session, const TileLayout& layout)
    : pipeservers_(static_cast<int>(layout.pipeservers.size())) {
  for (const PipeserverPlan& p : layout.pipeservers) {
    std::vector<Rect>& rects = tiles_.emplace_back();
    for (const PackedTile& t : p.tiles) rects.push_back(t.tile.on_canvas);
  }
  for (int k = 0; k < session.shares; ++k) {
    Slot& s = slots_.emplace_back();
    s.window = share_window_id(session, k);
    start_era(s, nullptr, 0);
  }
}

// A free slot's desktop is 1x1 and never sampled: no window of it is shown.
void SessionShares::start_era(Slot& slot, std::unique_ptr<DesktopSource> source, int from) {
  const int w = source ? source->width() : 1, h = source ? source->height() : 1;
  if (!slot.eras.empty() && slot.eras.back().from == from) slot.eras.pop_back();
  slot.eras.push_back(
      {from, std::move(source), std::make_unique<DesktopFrames>(w, h, pipeservers_)});
  if (slot.eras.size() > 2) slot.eras.erase(slot.eras.begin());
}

Result<int> SessionShares::free_window() const {
  const auto free =
      std::find_if(slots_.begin(), slots_.end(), [](const Slot& s) { return !s.open; });
  if (free != slots_.end()) return free->window;
  if (slots_.empty())
    return Failure{"the session takes no shares (give it shares = N, docs/session-file.md)"};
  return Failure{fmt::format("all {} share windows are in use (the session's shares = {})",
                             slots_.size(), slots_.size())};
}

void SessionShares::open(int window, std::unique_ptr<DesktopSource> source, const std::string& name,
                         int from) {
  for (Slot& s : slots_) {
    if (s.window != window) continue;
    opened_.push_back(fmt::format("shares: window {} shared by {} ({}x{}) from frame {}", window,
                                  name, source->width(), source->height(), from));
    s.open = true;
    start_era(s, std::move(source), from);
  }
}

bool SessionShares::close(int window) {
  for (Slot& s : slots_) {
    if (s.window != window || !s.open) continue;
    s.open = false;  // its desktop stays until the next share: its window is gone from the frames
    return true;
  }
  return false;
}

bool SessionShares::is_share(int window) const {
  return std::any_of(slots_.begin(), slots_.end(),
                     [&](const Slot& s) { return s.window == window; });
}

void SessionShares::take_updates() {
  for (Slot& s : slots_) {
    Era& latest = s.eras.back();
    if (s.open && latest.source)
      latest.source->take_updates(*latest.frames, std::chrono::milliseconds(0));
  }
}

SessionShares::Era& SessionShares::era_for(Slot& slot, int frame) {
  for (auto e = slot.eras.rbegin(); e != slot.eras.rend(); ++e)
    if (e->from <= frame) return *e;
  return slot.eras.front();
}

std::vector<std::string> SessionShares::answer(int pipeserver, int frame,
                                               const std::vector<WindowPlace>& shown) {
  std::vector<std::string> lines;
  const std::vector<Rect>& tiles = tiles_.at(static_cast<std::size_t>(pipeserver));
  for (Slot& s : slots_) {
    DesktopFrames& frames = *era_for(s, frame).frames;
    const std::vector<Rect> regions = desktop_regions(tiles, shown, {{s.window, SourceFit::Fit}},
                                                      frames.width(), frames.height());
    const std::vector<std::string> part = frames.answer(pipeserver, frame, regions);
    lines.insert(lines.end(), part.begin(), part.end());
  }
  return lines;
}

std::string SessionShares::summary() const {
  std::string out;
  for (const std::string& line : opened_) out += line + "\n";
  return out;
}

}  // namespace l2
