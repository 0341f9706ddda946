// Integer pixel rectangles, the unit of every layout decision.
#pragma once

#include <algorithm>

namespace l2 {

struct Rect {
  int x = 0, y = 0, w = 0, h = 0;

  int right() const { return x + w; }   // one past the last column
  int bottom() const { return y + h; }  // one past the last row
  long long area() const { return static_cast<long long>(w) * h; }
  bool empty() const { return w <= 0 || h <= 0; }
  bool contains(int px, int py) const {
    return px >= x && px < right() && py >= y && py < bottom();
  }
  friend bool operator==(const Rect&, const Rect&) = default;
};

inline Rect intersect(const Rect& a, const Rect& b) {
  const int x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
  const int x1 = std::min(a.right(), b.right()), y1 = std::min(a.bottom(), b.bottom());
  if (x1 <= x0 || y1 <= y0) return {};
  return {x0, y0, x1 - x0, y1 - y0};
}

}  // namespace l2
