// Byte-for-byte comparison of two pictures of one display (the DVI path against the
// vizserver path), with a picture of where they differ for the person debugging it.
#pragma once

#include <cstdint>

#include "image/rgb_image.hpp"

namespace l2 {

struct DisplayDiff {
  std::uint64_t differing_pixels = 0;  // every pixel when the sizes differ
  RgbImage picture;  // black where equal; where not, the per-channel difference, at least 64
  bool identical() const { return differing_pixels == 0; }
};

// Size mismatch: all pixels of the larger picture count as differing.
DisplayDiff compare_displays(const RgbImage& a, const RgbImage& b);

}  // namespace l2
