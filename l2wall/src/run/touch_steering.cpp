#include "touch_steering.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <set>

#include "control_page/http_address.hpp"

namespace l2 {
namespace {

std::string count(long n, const char* what, const char* plural = "s") {
  return fmt::format("{} {}{}", n, what, n == 1 ? "" : plural);
}

// "move ID ..." -> ID; -1 for another command.
int moved_window(const std::string& command) {
  int id = -1;
  return std::sscanf(command.c_str(), "move %d", &id) == 1 ? id : -1;
}

}  // namespace

void TouchSteering::start(const std::string& address, const Wall& wall) {
  if (address.empty()) return;
  const HttpAddress a = *parse_http_address(address);  // checked on the command line
  receiver_ = std::make_unique<TuioReceiver>(a.host, static_cast<std::uint16_t>(a.port));
  gestures_ = std::make_unique<Gestures>(wall.canvas_width, wall.canvas_height);
  std::fprintf(stderr, "l2wall: touch: TUIO on udp %s:%d\n", a.host.c_str(), receiver_->port());
}

std::vector<std::string> TouchSteering::commands(const RunWindows& windows, int frame) {
  if (!receiver_) return {};
  const std::vector<CursorFrame> frames = receiver_->poll();
  if (frames.empty()) return {};
  const std::vector<WindowPlace> shown = windows.shown_at(frame);
  std::vector<std::string> all;
  for (const CursorFrame& f : frames) {
    for (std::string& c : gestures_->take(f, shown)) all.push_back(std::move(c));
  }
  // From the last back: a move of a window moved again later is dropped.
  std::vector<std::string> kept;
  std::set<int> moved;
  for (auto c = all.rbegin(); c != all.rend(); ++c) {
    const int id = moved_window(*c);
    if (id >= 0 && !moved.insert(id).second) continue;
    kept.push_back(std::move(*c));
  }
  std::reverse(kept.begin(), kept.end());
  return kept;
}

std::string TouchSteering::summary() const {
  if (!receiver_) return {};
  const Gestures::Counts& c = gestures_->counts();
  return fmt::format("touch: {} ({}, {}, {}), {} moved, {} raised; {}, {} dropped\n",
                     count(c.taps + c.drags + c.pinches, "gesture"), count(c.taps, "tap"),
                     count(c.drags, "drag"), count(c.pinches, "pinch", "es"),
                     count(static_cast<long>(c.moved.size()), "window"), c.raised,
                     count(receiver_->dropped_packets(), "packet"),
                     count(receiver_->dropped_messages(), "message"));
}

}  // namespace l2
