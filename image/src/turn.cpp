#include "image/turn.hpp"

#include <cstring>

namespace l2 {

namespace {

// For each panel pixel, the canvas pixel its map names: one pass, rows of the output in order.
void fill_panel(const RgbImage& canvas, const PanelMap& m, RgbImage& panel) {
  const std::ptrdiff_t step = (static_cast<std::ptrdiff_t>(m.vx) * canvas.width() + m.ux) * 3;
  for (int y = 0; y < panel.height(); ++y) {
    const std::uint8_t* src =
        canvas.data() + (static_cast<std::ptrdiff_t>(m.v(0, y)) * canvas.width() + m.u(0, y)) * 3;
    std::uint8_t* dst = panel.row(y).data();
    for (int x = 0; x < panel.width(); ++x, src += step, dst += 3) std::memcpy(dst, src, 3);
  }
}

}  // namespace

RgbImage to_panel(const RgbImage& canvas, Orientation o) {
  if (o.identity()) return canvas;
  const int w = o.turned() ? canvas.height() : canvas.width();
  const int h = o.turned() ? canvas.width() : canvas.height();
  RgbImage panel = RgbImage::unfilled(w, h);
  fill_panel(canvas, panel_map(o, w, h), panel);
  return panel;
}

RgbImage to_canvas(const RgbImage& frame, Orientation o) {
  if (o.identity()) return frame;
  const PanelMap m = panel_map(o, frame.width(), frame.height());
  const int w = o.turned() ? frame.height() : frame.width();
  const int h = o.turned() ? frame.width() : frame.height();
  RgbImage canvas = RgbImage::unfilled(w, h);
  // The inverse map, a map from canvas to panel of the same kind: transpose and shift.
  const PanelMap inv{m.ux, m.vx, m.x_of(0, 0), m.uy, m.vy, m.y_of(0, 0)};
  fill_panel(frame, inv, canvas);
  return canvas;
}

}  // namespace l2
