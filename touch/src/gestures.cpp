#include "touch/gestures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tilelayout/session_file.hpp"

namespace l2 {
namespace {

// How far a finger may wander from where it landed, as a part of the canvas's longer side, and
// still tap: a touch frame's reports of a finger held still jitter by a few pixels.
constexpr double kSlopOfCanvas = 0.01;

double distance(double ax, double ay, double bx, double by) {
  return std::hypot(bx - ax, by - ay);
}

}  // namespace

Gestures::Gestures(int canvas_width, int canvas_height)
    : width_(canvas_width),
      height_(canvas_height),
      slop_(kSlopOfCanvas * std::max(canvas_width, canvas_height)) {}

std::vector<std::string> Gestures::take(const CursorFrame& f,
                                        std::span<const WindowPlace> windows) {
  std::vector<std::string> out;
  const auto down = [&f](std::int32_t id) {
    return std::any_of(f.cursors.begin(), f.cursors.end(),
                       [id](const Cursor& c) { return c.id == id; });
  };
  for (auto it = fingers_.begin(); it != fingers_.end();) {
    if (down(it->id)) {
      ++it;
      continue;
    }
    const Finger gone = *it;
    it = fingers_.erase(it);
    lift(gone, out);
  }
  // Every finger already down where it is now, before a new one anchors a window it shares.
  std::vector<const Cursor*> landing;
  for (const Cursor& c : f.cursors) {
    const Point p{c.x * width_, c.y * height_};
    const auto at = std::find_if(fingers_.begin(), fingers_.end(),
                                 [&c](const Finger& g) { return g.id == c.id; });
    if (at != fingers_.end()) {
      at->at = p;
    } else {
      landing.push_back(&c);
    }
  }
  for (const Cursor* c : landing) {
    const Point p{c->x * width_, c->y * height_};
    fingers_.push_back({c->id, p, p, -1});
    land(fingers_.back(), windows);
  }
  for (Hold& h : holds_) follow(h, out);
  return out;
}

// A finger lifted: the gesture of its window ends with its last finger (a tap raises it), or
// goes on from here with the fingers left.
void Gestures::lift(const Finger& f, std::vector<std::string>& out) {
  Hold* h = hold_of(f.window);
  if (!h) return;
  const auto at = std::find(h->fingers.begin(), h->fingers.end(), f.id);
  const bool counted = at - h->fingers.begin() < 2;
  h->fingers.erase(at);
  if (!h->fingers.empty()) {
    if (counted) anchor(*h);
    return;
  }
  if (h->pinched) {
    ++counts_.pinches;
  } else if (h->dragged) {
    ++counts_.drags;
  } else {
    ++counts_.taps;
    ++counts_.raised;
    out.push_back(fmt::format("raise {}", h->window));
  }
  holds_.erase(holds_.begin() + (h - holds_.data()));
}

// A finger down: it holds the front-most window under it, where a gesture may have moved it.
void Gestures::land(Finger& f, std::span<const WindowPlace> windows) {
  for (auto w = windows.rbegin(); w != windows.rend(); ++w) {
    const Hold* held = hold_of(w->id);
    const Box b =
        held ? held->now
             : Box{static_cast<double>(w->on_canvas.x), static_cast<double>(w->on_canvas.y),
                   static_cast<double>(w->on_canvas.w), static_cast<double>(w->on_canvas.h)};
    if (f.at.x < b.x || f.at.y < b.y || f.at.x >= b.x + b.w || f.at.y >= b.y + b.h) continue;
    f.window = w->id;
    if (Hold* h = hold_of(w->id)) {
      h->fingers.push_back(f.id);
      if (h->fingers.size() <= 2) anchor(*h);
    } else {
      Hold n{w->id, {f.id}, b, b, {}, w->on_canvas};
      anchor(n);
      holds_.push_back(std::move(n));
    }
    return;
  }
}

// Where the window goes for where its fingers are now, and the move when that is a new place.
void Gestures::follow(Hold& h, std::vector<std::string>& out) {
  Box b = h.anchor;
  if (h.fingers.size() == 1) {
    const Finger& f = finger(h.fingers[0]);
    if (!h.dragged && !h.pinched && distance(f.landed.x, f.landed.y, f.at.x, f.at.y) <= slop_)
      return;
    h.dragged = true;
    b.x += f.at.x - h.anchor_at[0].x;
    b.y += f.at.y - h.anchor_at[0].y;
  } else {
    const Point p0 = finger(h.fingers[0]).at, p1 = finger(h.fingers[1]).at;
    const Point a0 = h.anchor_at[0], a1 = h.anchor_at[1];
    const double was = distance(a0.x, a0.y, a1.x, a1.y);
    double s = was >= 1.0 ? distance(p0.x, p0.y, p1.x, p1.y) / was : 1.0;
    // Within the sides a window may have, keeping its shape.
    const double least = std::max(1.0 / h.anchor.w, 1.0 / h.anchor.h);
    const double most = std::min(kMaxWindowSide / h.anchor.w, kMaxWindowSide / h.anchor.h);
    s = std::max(least, std::min(s, most));
    const Point c0{(a0.x + a1.x) / 2, (a0.y + a1.y) / 2}, c{(p0.x + p1.x) / 2, (p0.y + p1.y) / 2};
    b = {c.x - (c0.x - h.anchor.x) * s, c.y - (c0.y - h.anchor.y) * s, h.anchor.w * s,
         h.anchor.h * s};
    h.pinched = true;
  }
  h.now = b;
  const auto whole = [](double v, int lo, int hi) {
    return static_cast<int>(std::clamp(std::lround(v), long{lo}, long{hi}));
  };
  const Rect r{whole(b.x, -kWindowReach, kWindowReach), whole(b.y, -kWindowReach, kWindowReach),
               whole(b.w, 1, kMaxWindowSide), whole(b.h, 1, kMaxWindowSide)};
  if (r == h.said) return;
  h.said = r;
  counts_.moved.insert(h.window);
  out.push_back(fmt::format("move {} {} {} {} {}", h.window, r.x, r.y, r.w, r.h));
}

// The window's place and its counted fingers' now: what the gesture goes on from.
void Gestures::anchor(Hold& h) {
  h.anchor = h.now;
  h.anchor_at.clear();
  for (std::size_t k = 0; k < h.fingers.size() && k < 2; ++k)
    h.anchor_at.push_back(finger(h.fingers[k]).at);
}

const Gestures::Finger& Gestures::finger(std::int32_t id) const {
  return *std::find_if(fingers_.begin(), fingers_.end(),
                       [id](const Finger& f) { return f.id == id; });
}

Gestures::Hold* Gestures::hold_of(int window) {
  const auto at = std::find_if(holds_.begin(), holds_.end(),
                               [window](const Hold& h) { return h.window == window; });
  return at == holds_.end() ? nullptr : &*at;
}

}  // namespace l2
