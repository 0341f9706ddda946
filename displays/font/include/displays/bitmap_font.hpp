// A tiny built-in 5x7 bitmap font for the overlay line, so the wall window needs no font files.
// Letters are drawn as capitals (lower case maps to them); an unknown character draws a box.
#pragma once

#include <string_view>

#include "image/rgb_image.hpp"

namespace l2 {

inline constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6;

// Width in pixels of `text` drawn at `scale` (each font pixel becomes scale x scale).
int text_width(std::string_view text, int scale);

// Draws `text` with its top-left corner at (x, y); pixels outside the image are skipped.
void draw_text(RgbImage& image, int x, int y, std::string_view text, Rgb colour, int scale);

}  // namespace l2
