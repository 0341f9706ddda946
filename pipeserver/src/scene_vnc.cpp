#include "scene_vnc.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "scene_common.hpp"

namespace l2::detail {

void DesktopScene::hold(int width, int height, const std::vector<Rect>& regions) {
  std::vector<Region> next;
  for (const Rect& r : regions) {
    const auto before = std::find_if(regions_.begin(), regions_.end(),
                                     [&r](const Region& g) { return g.rect == r; });
    if (before != regions_.end() && width == width_ && height == height_)
      next.push_back(std::move(*before));
    else
      next.push_back({r, RgbImage(r.w, r.h)});
  }
  regions_ = std::move(next);
  width_ = width;
  height_ = height;
}

void DesktopScene::put(const Rect& r, const std::uint8_t* rgb) {
  for (Region& g : regions_) {
    if (intersect(g.rect, r) != r) continue;
    const std::size_t row = static_cast<std::size_t>(r.w) * 3;
    for (int y = 0; y < r.h; ++y)
      std::copy_n(rgb + y * row, row,
                  g.pixels.row(r.y - g.rect.y + y).data() + (r.x - g.rect.x) * 3);
    return;
  }
  throw std::invalid_argument(fmt::format(
      "desktop: rectangle {},{} {}x{} is in no region this pipeserver holds", r.x, r.y, r.w, r.h));
}

bool DesktopScene::fill_tile(const Canvas& /*canvas*/, const Rect& on_canvas, RgbImage& rgb) const {
  rgb = RgbImage(on_canvas.w, on_canvas.h);
  for (const Region& g : regions_) {
    const Rect part = intersect(g.rect, on_canvas);
    for (int y = part.y; y < part.bottom(); ++y)
      std::copy_n(g.pixels.row(y - g.rect.y).data() + (part.x - g.rect.x) * 3, part.w * 3,
                  rgb.row(y - on_canvas.y).data() + (part.x - on_canvas.x) * 3);
  }
  return true;
}

std::unique_ptr<Scene> make_vnc_scene(const std::string& address) {
  return std::make_unique<DesktopScene>(address);
}

}  // namespace l2::detail
