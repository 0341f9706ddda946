// Labels, legends and the overlay line: text in DejaVu Sans Mono (image/text.hpp), blended
// onto a picture. Layout is in capital heights: text drawn at `scale` has capitals
// kTextHeight * scale pixels tall, descenders below them.
#pragma once

#include <string_view>

#include "image/rgb_image.hpp"

namespace l2 {

inline constexpr int kTextHeight = 7;

// Width in pixels of `text` drawn at `scale`.
int text_width(std::string_view text, int scale);

// Draws `text` with the top of its capitals at y (the dot of an i above), starting at x; each
// pixel is blended towards `colour` by how much of it the text covers. Pixels outside the image
// are skipped. Throws std::runtime_error when the font cannot be found (image/text.hpp).
void draw_text(RgbImage& image, int x, int y, std::string_view text, Rgb colour, int scale);

}  // namespace l2
