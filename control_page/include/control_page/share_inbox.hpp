// Screens shared from the page's browsers (control_page/README.md), from the HTTP server's
// threads to the run's: each share is a window of the run, opened by the run's decision on a
// share request; its frames arrive as JPEG bodies, decoded here (jpeg_frame.hpp) and kept newest
// only, so a browser faster than the wall loses frames rather than queueing them. It owns the
// shares' newest frames and their counts; the run takes the frames at frame boundaries.
// Memory is bounded: one frame kept and at most one being decoded per share.
#pragma once

#include <chrono>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "control_page/control_inbox.hpp"
#include "control_page/run_state.hpp"
#include "image/rgb_image.hpp"

namespace l2 {

// The largest frames a screen may be shared with: a 4K screen.
inline constexpr int kMaxShareWidth = 3840, kMaxShareHeight = 2160;

class ShareInbox {
 public:
  using Clock = std::chrono::steady_clock;

  // The run opened window `window` for a share of width x height frames from `name`.
  void open(int window, std::string name, int width, int height);
  // The share's window closed (the page's Stop, or a close): its frames are refused from now on.
  void close(int window);

  // Whether a frame for `window` may be read now: 200, or a refusal (404: no such share, 429:
  // its last frame is still being decoded) with its one-line reason. A frame admitted must be
  // given to put() or to drop().
  ControlDecision admit(int window);
  // A frame admitted for `window`: decoded and kept as its newest, or refused (400) in one line.
  ControlDecision put(int window, std::string_view jpeg);
  // An admitted frame whose body never came whole.
  void drop(int window);

  // The run's side: `window`'s newest frame since the last take, if one came.
  std::optional<RgbImage> take(int window);
  // Every open share as the page shows it.
  std::vector<PageShare> shares(Clock::time_point now) const;

 private:
  struct Share {
    int window = 0;
    std::string name;
    int width = 0, height = 0;
    std::optional<RgbImage> newest;
    bool decoding = false;
    long received = 0, shown = 0, dropped = 0, refused = 0;
    Clock::time_point last{};  // of the last frame received; none: the epoch
  };
  Share* find(int window);

  mutable std::mutex mutex_;
  std::vector<Share> shares_;
};

}  // namespace l2
