// A legend under a picture written for people: one line per entry, a colour swatch and what it
// means, in the label text (label_text.hpp), large enough to read when the picture is
// viewed scaled down to a screen.
#pragma once

#include <span>
#include <string>

#include "image/rgb_image.hpp"

namespace l2 {

struct LegendEntry {
  std::string text;
  Rgb colour{};
  bool swatch = true;  // false: a line of text only
};

// The font scale for a picture `width` pixels wide: 1 up to 640, then one more per 640.
int legend_scale(int width);

// `picture` with the legend below it (black), as wide as the wider of the two.
RgbImage with_legend(const RgbImage& picture, std::span<const LegendEntry> entries);

}  // namespace l2
