#include "desktop_frames.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "balance/desktop_messages.hpp"

namespace l2 {
namespace {

// Past this many rectangles a frame's damage is kept as their bounding box: a desktop that
// changes in many small places costs a few more pixels, never a long list.
constexpr std::size_t kMaxDamageRects = 64;

Rect bounding(const Rect& a, const Rect& b) {
  const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
  return {x0, y0, std::max(a.right(), b.right()) - x0, std::max(a.bottom(), b.bottom()) - y0};
}

void add_damage(std::vector<Rect>& damage, const Rect& r) {
  for (const Rect& d : damage)
    if (intersect(d, r) == r) return;  // already inside one
  damage.push_back(r);
  if (damage.size() <= kMaxDamageRects) return;
  Rect all = damage.front();
  for (const Rect& d : damage) all = bounding(all, d);
  damage.assign(1, all);
}

// Pipeservers are at most a frame apart (each waits for READY of the frame before): a few
// frames cover them with room to spare.
constexpr std::size_t kMaxKept = 4;

}  // namespace

DesktopFrames::DesktopFrames(int width, int height, int pipeservers)
    : live_(width, height), held_(static_cast<std::size_t>(pipeservers)) {}

void DesktopFrames::damaged(const Rect& r) {
  const Rect clipped = intersect(r, {0, 0, width(), height()});
  if (!clipped.empty()) add_damage(damage_, clipped);
}

const DesktopFrames::Frozen& DesktopFrames::frozen(int frame) {
  for (const Frozen& f : frozen_)
    if (f.frame == frame) return f;
  const int next = frozen_.empty() ? frame : frozen_.back().frame + 1;
  if (frame != next)
    throw DesktopError(
        fmt::format("desktop: frame {} asked for while frame {} is next", frame, next));
  Frozen f;
  f.frame = frame;
  f.picture = !frozen_.empty() && damage_.empty() ? frozen_.back().picture
                                                  : std::make_shared<const RgbImage>(live_);
  f.damage = std::move(damage_);
  damage_.clear();
  frozen_.push_back(std::move(f));
  return frozen_.back();
}

// What changed in frames after+1 .. frame; a frame no longer kept counts as the whole desktop.
std::vector<Rect> DesktopFrames::changed_since(int after, int frame) const {
  std::vector<Rect> changed;
  for (int k = after + 1; k <= frame; ++k) {
    const auto at =
        std::find_if(frozen_.begin(), frozen_.end(), [k](const Frozen& f) { return f.frame == k; });
    if (at == frozen_.end()) return {{0, 0, width(), height()}};
    for (const Rect& r : at->damage) add_damage(changed, r);
  }
  return changed;
}

std::vector<std::string> DesktopFrames::answer(int pipeserver, int frame,
                                               const std::vector<Rect>& tiles) {
  if (pipeserver < 0 || pipeserver >= static_cast<int>(held_.size()))
    throw DesktopError(fmt::format("desktop: no pipeserver {}", pipeserver));
  Held& held = held_[static_cast<std::size_t>(pipeserver)];
  if (frame <= held.frame)
    throw DesktopError(fmt::format("desktop: pipeserver {} asked for frame {} after frame {}",
                                   pipeserver, frame, held.frame));
  const Frozen& f = frozen(frame);
  std::vector<Rect> regions;
  for (const Rect& t : tiles) {
    const Rect r = intersect(t, {0, 0, width(), height()});
    if (!r.empty()) regions.push_back(r);
  }
  // A region it did not hold in its last frame goes whole; the rest, what changed since.
  const std::vector<Rect> whole{{0, 0, width(), height()}};
  const std::vector<Rect> changed =
      held.frame < 0 || held.regions != regions ? whole : changed_since(held.frame, frame);
  std::vector<std::string> lines(1);
  const RgbImage& picture = *f.picture;
  for (const Rect& region : regions) {
    for (const Rect& c : changed) {
      const Rect part = intersect(region, c);
      if (part.empty()) continue;
      for (const Rect& band : desktop_bands(part))
        lines.push_back(
            encode_desktop_rect(band, picture.row(band.y).data() + band.x * 3, picture.stride()));
    }
  }
  lines.front() =
      encode(DesktopMessage{frame, width(), height(), regions, static_cast<int>(lines.size()) - 1});
  held.frame = frame;
  held.regions = std::move(regions);
  forget_sent();
  return lines;
}

// Frames every pipeserver has been sent are no longer needed, but for the last one: the next
// frame shares its picture when nothing changes. A pipeserver that stopped asking (it died)
// holds back no more than kMaxKept: should it ask again, it is sent its regions whole.
void DesktopFrames::forget_sent() {
  int oldest = held_.front().frame;
  for (const Held& h : held_) oldest = std::min(oldest, h.frame);
  while (frozen_.size() > 1 && (frozen_.front().frame <= oldest || frozen_.size() > kMaxKept))
    frozen_.pop_front();
}

}  // namespace l2
