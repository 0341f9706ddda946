// What a display applies to its pixels where they leave the wall (docs/wall-file.md, "Colour
// matching"): nothing, a gain and offset per channel, or a measured table read from a file.
// Either way it is one ColourTable (image/colour_table.hpp), built when the wall is read; what
// was written is kept only so that it can be said back (tilelayout's display lines).
#pragma once

#include <array>
#include <string>

#include "image/colour_table.hpp"

namespace l2 {

struct ColourMatch {
  enum class Kind { None, Gain, Lut };
  Kind kind = Kind::None;
  std::array<double, 3> gain{1.0, 1.0, 1.0};  // Kind::Gain: as written
  std::array<int, 3> offset{0, 0, 0};
  std::string lut;  // Kind::Lut: the file as written, relative to the wall file
  ColourTable table = ColourTable::identity();

  // Whether pixels change at all: a correction that works out to the identity costs nothing.
  bool applies() const { return kind != Kind::None && !table.is_identity(); }
};

}  // namespace l2
