// A display's measured colour table as a text file (docs/wall-file.md, "Colour table files"):
// 256 lines `R G B` of integers 0..255, the line for input byte i giving the three channels'
// outputs for i, with `#` comments and blank lines anywhere.
//
// Example:
//   const ColourTable t = parse_colour_lut(text, "calibration/panel-3.txt");
//   // refused: "calibration/panel-3.txt:17: expected 3 integers 0..255, got \"12 300 4\""
#pragma once

#include <cstddef>
#include <string_view>

#include "image/colour_table.hpp"

namespace l2 {

// A table file is 256 short lines; anything much larger is not one (a picture, a log).
inline constexpr std::size_t kMaxColourLutBytes = 64 * 1024;

// Parses table text; `name` starts every error. Throws LayoutError, one line naming the file,
// the line and what is wrong: a bad entry, more or fewer than 256 entries, text over
// kMaxColourLutBytes.
ColourTable parse_colour_lut(std::string_view text, std::string_view name);

}  // namespace l2
