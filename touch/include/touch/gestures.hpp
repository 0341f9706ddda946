// Gestures on the wall's windows: committed cursor frames (tuio_cursors.hpp) and the windows as
// the wall shows them become the window commands the control page and --window-stdin give
// ("move ID X Y W H", "raise ID"; l2wall/src/desktops/live_windows.hpp). It owns the fingers
// down and the window each holds; it keeps no time and does no I/O.
//
// A finger lands on the front-most window under it (cursors' 0..1 span the whole canvas) and
// holds that window until it lifts; on no window it holds nothing. With one finger on a window
// a drag moves it once the finger has gone further than a slop from where it landed; with two,
// a pinch scales it about the fingers' centre by the change in their distance and moves it with
// that centre (a third finger on it is ignored). A finger that lifts before leaving the slop,
// having held its window alone, is a tap: the window is raised. When a window's fingers change,
// its gesture goes on from where the window is, without a jump.
//
//   Gestures gestures(wall.canvas_width, wall.canvas_height);
//   for (const std::string& command : gestures.take(frame, windows)) run(command);
#pragma once

#include <set>
#include <span>
#include <string>
#include <vector>

#include "balance/control_messages.hpp"
#include "touch/tuio_cursors.hpp"

namespace l2 {

class Gestures {
 public:
  Gestures(int canvas_width, int canvas_height);

  // The commands frame `f` asks for, given `windows` as shown (back to front). A window held by
  // a gesture is where the gesture put it, whatever `windows` says until the wall catches up.
  std::vector<std::string> take(const CursorFrame& f, std::span<const WindowPlace> windows);

  // Ended gestures by kind, and what they did.
  struct Counts {
    int taps = 0, drags = 0, pinches = 0;
    int raised = 0;
    std::set<int> moved;  // windows moved or resized
  };
  const Counts& counts() const { return counts_; }

 private:
  struct Point {
    double x = 0, y = 0;
  };
  struct Box {
    double x = 0, y = 0, w = 0, h = 0;
  };
  struct Finger {
    std::int32_t id = 0;
    Point at, landed;
    int window = -1;  // the window it holds, -1: none
  };
  // A window held by fingers: where it was when they last changed, where it is now.
  struct Hold {
    int window = 0;
    std::vector<std::int32_t> fingers;  // the first two count
    Box anchor, now;
    std::vector<Point> anchor_at;  // the counted fingers where they were at the anchor
    Rect said;                     // the last place commanded
    bool dragged = false, pinched = false;
  };

  void lift(const Finger& f, std::vector<std::string>& out);
  void land(Finger& f, std::span<const WindowPlace> windows);
  void follow(Hold& h, std::vector<std::string>& out);
  void anchor(Hold& h);
  const Finger& finger(std::int32_t id) const;
  Hold* hold_of(int window);

  const int width_, height_;
  const double slop_;  // canvas pixels a finger may wander and still tap
  std::vector<Finger> fingers_;
  std::vector<Hold> holds_;
  Counts counts_;
};

}  // namespace l2
