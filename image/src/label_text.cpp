#include "image/label_text.hpp"

#include <cstdint>

#include "image/text.hpp"

namespace l2 {

namespace {

std::uint8_t blend(std::uint8_t under, std::uint8_t ink, int coverage) {
  return static_cast<std::uint8_t>((under * (255 - coverage) + ink * coverage + 127) / 255);
}

}  // namespace

int text_width(std::string_view text, int scale) {
  return render_text(text, kTextHeight * scale).width;
}

void draw_text(RgbImage& image, int x, int y, std::string_view text, Rgb colour, int scale) {
  const TextMask mask = render_text(text, kTextHeight * scale);
  for (int my = 0; my < mask.height; ++my) {
    const int iy = y - mask.above + my;
    if (iy < 0 || iy >= image.height()) continue;
    for (int mx = 0; mx < mask.width; ++mx) {
      const int ix = x + mx;
      const int coverage = mask.coverage[static_cast<std::size_t>(my) * mask.width + mx];
      if (ix < 0 || ix >= image.width() || coverage == 0) continue;
      const Rgb p = image.at(ix, iy);
      image.set(ix, iy,
                {blend(p.r, colour.r, coverage), blend(p.g, colour.g, coverage),
                 blend(p.b, colour.b, coverage)});
    }
  }
}

}  // namespace l2
