#include "digit_font.hpp"

#include <string>

namespace l2 {
namespace {

// Rows top to bottom, bit 2 = left column.
constexpr unsigned char kDigits[10][5] = {
    {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
    {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7}};

}  // namespace

int number_width(int value, int scale) {
  const int digits = static_cast<int>(std::to_string(value).size());
  return (4 * digits - 1) * scale;
}

void draw_number(RgbImage& image, int x, int y, int value, int scale, Rgb colour) {
  const std::string text = std::to_string(value);
  for (char ch : text) {
    if (ch < '0' || ch > '9') continue;
    const auto& glyph = kDigits[ch - '0'];
    for (int row = 0; row < 5; ++row) {
      for (int col = 0; col < 3; ++col) {
        if (glyph[row] >> (2 - col) & 1) {
          image.fill_rect(x + col * scale, y + row * scale, scale, scale, colour);
        }
      }
    }
    x += 4 * scale;
  }
}

}  // namespace l2
