#include "scene_vnc.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "scene_common.hpp"
#include "source_fill.hpp"

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
  if (std::none_of(regions_.begin(), regions_.end(),
                   [&r](const Region& g) { return intersect(g.rect, r) == r; }))
    throw std::invalid_argument(
        fmt::format("desktop: rectangle {},{} {}x{} is in no region this pipeserver holds", r.x,
                    r.y, r.w, r.h));
  const std::size_t row = static_cast<std::size_t>(r.w) * 3;
  for (Region& g : regions_) {
    const Rect part = intersect(g.rect, r);
    for (int y = part.y; y < part.bottom(); ++y)
      std::copy_n(rgb + (y - r.y) * row + (part.x - r.x) * 3, part.w * 3,
                  g.pixels.row(y - g.rect.y).data() + (part.x - g.rect.x) * 3);
  }
}

void DesktopScene::read_row(int y, int x_begin, int x_end, std::uint8_t* rgb) const {
  const Rect span{x_begin, y, x_end - x_begin, 1};
  for (const Region& g : regions_) {
    if (intersect(g.rect, span) != span) continue;
    std::copy_n(g.pixels.row(y - g.rect.y).data() + (x_begin - g.rect.x) * 3, span.w * 3, rgb);
    return;
  }
  std::fill_n(rgb, static_cast<std::size_t>(span.w) * 3, std::uint8_t{0});
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

namespace {

class DesktopWindow : public Scene {
 public:
  DesktopWindow(const DesktopScene& desktop, SourceFit fit) : desktop_(desktop), fit_(fit) {
    lit_ = false;
  }
  const char* name() const override { return "vnc"; }

  bool fill_tile(const Canvas& canvas, const Rect& on_canvas, RgbImage& rgb) const override {
    const int w = desktop_.width(), h = desktop_.height();
    fill_from_source(
        movie_view(std::max(w, 1), std::max(h, 1), canvas, fit_), w, h, canvas, on_canvas,
        [this](int y, int x_begin, int x_end, std::uint8_t* out) {
          desktop_.read_row(y, x_begin, x_end, out);
        },
        rgb);
    return true;
  }

 protected:
  void animate(int /*frame*/) override {}

 private:
  const DesktopScene& desktop_;
  SourceFit fit_;
};

}  // namespace

std::unique_ptr<Scene> make_desktop_window(const DesktopScene& desktop, SourceFit fit) {
  return std::make_unique<DesktopWindow>(desktop, fit);
}

std::unique_ptr<Scene> make_vnc_scene(const std::string& address) {
  return std::make_unique<DesktopScene>(address);
}

}  // namespace l2::detail
