#include "wall_picture.hpp"

#include <algorithm>
#include <cstring>

#include "image/turn.hpp"

namespace l2 {

RgbImage compose_wall_picture(const Wall& wall,
                              const std::function<const RgbImage&(int display)>& shown) {
  int w = std::max(wall.canvas_width, 1), h = std::max(wall.canvas_height, 1);
  for (const Display& d : wall.displays) {
    w = std::max(w, d.on_canvas().right());
    h = std::max(h, d.on_canvas().bottom());
  }
  RgbImage picture(w, h, Rgb{40, 40, 40});
  for (const Display& d : wall.displays) {
    // As the display hangs: a turned panel's frame turned back onto its canvas rectangle.
    RgbImage turned;
    const RgbImage& frame = shown(d.id);
    if (!d.orientation.identity()) turned = to_canvas(frame, d.orientation);
    const RgbImage& img = d.orientation.identity() ? frame : turned;
    // Clip to the picture: a display may start left of or above the canvas origin.
    const int x0 = std::max(0, -d.canvas_x), y0 = std::max(0, -d.canvas_y);
    const int cols = std::min(img.width(), w - d.canvas_x) - x0;
    if (cols <= 0) continue;
    for (int y = y0; y < img.height() && d.canvas_y + y < h; ++y) {
      std::memcpy(picture.row(d.canvas_y + y).data() + (d.canvas_x + x0) * 3,
                  img.row(y).data() + x0 * 3, static_cast<std::size_t>(cols) * 3);
    }
  }
  return picture;
}

}  // namespace l2
