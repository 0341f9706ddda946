#include "image/legend.hpp"

#include <algorithm>

#include "image/label_text.hpp"

namespace l2 {
namespace {

constexpr Rgb kText{230, 230, 230};

}  // namespace

int legend_scale(int width) {
  return std::max(1, width / 640);
}

RgbImage with_legend(const RgbImage& picture, std::span<const LegendEntry> entries) {
  const int s = legend_scale(picture.width());
  const int line = (kTextHeight + 3) * s, text_x = (kTextHeight + 5) * s;
  int width = picture.width();
  for (const LegendEntry& e : entries) {
    width = std::max(width, text_x + text_width(e.text, s) + 2 * s);
  }
  const int height = picture.height() + static_cast<int>(entries.size()) * line + 4 * s;
  RgbImage out(width, height);
  for (int y = 0; y < picture.height(); ++y) {
    std::copy(picture.row(y).begin(), picture.row(y).end(), out.row(y).begin());
  }
  int y = picture.height() + 2 * s;
  for (const LegendEntry& e : entries) {
    if (e.swatch) out.fill_rect(2 * s, y, kTextHeight * s, kTextHeight * s, e.colour);
    draw_text(out, text_x, y, e.text, kText, s);
    y += line;
  }
  return out;
}

}  // namespace l2
