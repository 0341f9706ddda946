#include "pipeserver/bucketing.hpp"

#include <algorithm>
#include <cmath>

namespace l2 {

Rect canvas_footprint(const Canvas& canvas, const glm::mat4& clip_from_model, const Box& box) {
  const Rect whole{0, 0, canvas.width, canvas.height};
  if (box.lo.x > box.hi.x) return {};  // an empty box covers nothing
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  const glm::dmat4 m(clip_from_model);
  for (int c = 0; c < 8; ++c) {
    const glm::dvec4 corner(c & 1 ? box.hi.x : box.lo.x, c & 2 ? box.hi.y : box.lo.y,
                            c & 4 ? box.hi.z : box.lo.z, 1.0);
    const glm::dvec4 clip = m * corner;
    if (clip.w <= 1e-6) return whole;
    const glm::dvec2 p = clip_to_canvas(canvas, clip);
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  // Clamp before converting so far-off boxes cannot overflow int.
  const auto clamp = [](double v, double hi) { return std::clamp(v, -1.0, hi + 1.0); };
  const int ix0 = static_cast<int>(std::floor(clamp(x0, canvas.width))) - 1;
  const int iy0 = static_cast<int>(std::floor(clamp(y0, canvas.height))) - 1;
  const int ix1 = static_cast<int>(std::ceil(clamp(x1, canvas.width))) + 1;
  const int iy1 = static_cast<int>(std::ceil(clamp(y1, canvas.height))) + 1;
  return intersect(Rect{ix0, iy0, ix1 - ix0, iy1 - iy0}, whole);
}

}  // namespace l2
