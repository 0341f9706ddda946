// The coordinator's desktop (--scene vnc, docs/vnc.md): pure logic, no I/O. The desktop source
// (desktop_source.hpp) keeps `live()` up to date and says what it changed; the first WANT for a
// frame freezes live() as that frame's desktop, and every pipeserver is sent its part of that
// one frozen picture, whenever it asks: so all of them show the same state of the desktop in
// every frame, never one a step ahead of its neighbour. A pipeserver is sent only the
// rectangles its tiles show that changed since the last frame it was sent.
#pragma once

#include <deque>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/rgb_image.hpp"
#include "tilelayout/geometry.hpp"

namespace l2 {

// A desktop that cannot be shown: what() is one line.
class DesktopError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class DesktopFrames {
 public:
  DesktopFrames(int width, int height, int pipeservers);

  int width() const { return live_.width(); }
  int height() const { return live_.height(); }
  // The desktop as the source has it now.
  RgbImage& live() { return live_; }
  // The source changed `r` of live() (clipped to the desktop).
  void damaged(const Rect& r);
  // Whether live() changed since the last frame frozen.
  bool changed() const { return !damage_.empty(); }

  // The lines that answer `pipeserver`'s WANT for `frame` (DESKTOP and its RECTs,
  // balance/desktop_messages.hpp); `tiles`: its tiles' canvas rectangles. A frame is asked for
  // in order by each pipeserver, never more than one ahead of the last frame frozen: throws
  // DesktopError otherwise.
  std::vector<std::string> answer(int pipeserver, int frame, const std::vector<Rect>& tiles);

  // Frames frozen and still kept (some pipeserver has yet to be sent them), for tests.
  std::size_t kept() const { return frozen_.size(); }

 private:
  struct Frozen {
    int frame = 0;
    std::shared_ptr<const RgbImage> picture;  // shared with the frame before when nothing changed
    std::vector<Rect> damage;                 // since the frame before
  };
  struct Held {
    int frame = -1;  // the last frame it was sent; -1: none yet
    std::vector<Rect> regions;
  };

  const Frozen& frozen(int frame);
  std::vector<Rect> changed_since(int after, int frame) const;
  void forget_sent();

  RgbImage live_;
  std::vector<Rect> damage_;  // since the last frame frozen
  std::deque<Frozen> frozen_;
  std::vector<Held> held_;  // by pipeserver
};

}  // namespace l2
