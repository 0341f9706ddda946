#include "control_page/share_inbox.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "image/jpeg_frame.hpp"

namespace l2 {

ShareInbox::Share* ShareInbox::find(int window) {
  const auto at = std::find_if(shares_.begin(), shares_.end(),
                               [&](const Share& s) { return s.window == window; });
  return at == shares_.end() ? nullptr : &*at;
}

void ShareInbox::open(int window, std::string name, int width, int height) {
  const std::lock_guard lock(mutex_);
  shares_.erase(std::remove_if(shares_.begin(), shares_.end(),
                               [&](const Share& s) { return s.window == window; }),
                shares_.end());
  Share s;
  s.window = window;
  s.name = std::move(name);
  s.width = width;
  s.height = height;
  shares_.push_back(std::move(s));
}

void ShareInbox::close(int window) {
  const std::lock_guard lock(mutex_);
  shares_.erase(std::remove_if(shares_.begin(), shares_.end(),
                               [&](const Share& s) { return s.window == window; }),
                shares_.end());
}

ControlDecision ShareInbox::admit(int window) {
  const std::lock_guard lock(mutex_);
  Share* s = find(window);
  if (!s)
    return {404,
            fmt::format("frame refused: window {} shares no screen (stopped, or never started)",
                        window)};
  if (s->decoding)
    return {429, fmt::format("frame refused: window {}'s last frame is still being taken (send "
                             "the next after its answer)",
                             window)};
  s->decoding = true;
  return {200, {}};
}

void ShareInbox::drop(int window) {
  const std::lock_guard lock(mutex_);
  if (Share* s = find(window)) s->decoding = false;
}

ControlDecision ShareInbox::put(int window, std::string_view jpeg) {
  int width = 0, height = 0;
  {
    const std::lock_guard lock(mutex_);
    Share* s = find(window);
    if (!s) return {404, fmt::format("frame refused: window {} shares no screen any more", window)};
    width = s->width;
    height = s->height;
  }
  // Decoded outside the lock: the run's take() never waits for a decode.
  Result<RgbImage> frame = decode_jpeg_frame(jpeg, {width, height, JpegFrameLimits{}.max_bytes});
  const std::lock_guard lock(mutex_);
  Share* s = find(window);
  if (!s) return {404, fmt::format("frame refused: window {} shares no screen any more", window)};
  s->decoding = false;
  if (frame.ok() && (frame->width() != width || frame->height() != height))
    frame = Failure{fmt::format("{}x{}, but the share's frames are {}x{}", frame->width(),
                                frame->height(), width, height)};
  if (!frame.ok()) {
    ++s->refused;
    return {400, "frame refused: " + frame.reason()};
  }
  if (s->newest) ++s->dropped;  // the run had not taken the one before: never shown
  s->newest = std::move(frame).value();
  ++s->received;
  s->last = Clock::now();
  return {200, fmt::format("frame {} of window {} taken", s->received, window)};
}

std::optional<RgbImage> ShareInbox::take(int window) {
  const std::lock_guard lock(mutex_);
  Share* s = find(window);
  if (!s || !s->newest) return std::nullopt;
  std::optional<RgbImage> out = std::move(s->newest);
  s->newest.reset();
  ++s->shown;
  return out;
}

std::vector<PageShare> ShareInbox::shares(Clock::time_point now) const {
  const std::lock_guard lock(mutex_);
  std::vector<PageShare> out;
  for (const Share& s : shares_) {
    PageShare p;
    p.window = s.window;
    p.name = s.name;
    p.width = s.width;
    p.height = s.height;
    p.received = s.received;
    p.shown = s.shown;
    p.dropped = s.dropped;
    p.refused = s.refused;
    p.seconds_since_frame =
        s.received == 0 ? -1.0 : std::chrono::duration<double>(now - s.last).count();
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace l2
