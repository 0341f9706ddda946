// Comparison of two pictures of one display (the DVI path against the vizserver path, a
// display against its golden image or its reference render), with pictures of where they
// differ for the person debugging it.
#pragma once

#include <cstdint>

#include "image/rgb_image.hpp"

namespace l2 {

struct DisplayDiff {
  std::uint64_t differing_pixels = 0;  // every pixel when the sizes differ
  std::uint64_t beyond_one = 0;        // pixels where some channel differs by more than one level
  int largest = 0;                     // the largest channel difference (255 when sizes differ)
  int largest_x = -1, largest_y = -1;  // the first pixel (row-major) where it occurs
  bool size_differs = false;
  RgbImage picture;  // black where equal; where not, the per-channel difference, at least 64
  bool identical() const { return differing_pixels == 0; }
};

// Size mismatch: all pixels of the larger picture count as differing.
DisplayDiff compare_displays(const RgbImage& a, const RgbImage& b);

// A picture in which even one differing pixel is easy to find: `actual` dimmed to a quarter
// (so its content still shows where the difference is), every differing pixel magenta, and
// (while there are at most kMarkedPixels of them) a yellow square around each, 13 pixels wide
// (a hundredth of the picture's larger side on large ones).
// Sizes differ: `actual` dimmed with a magenta border, as nothing can be lined up.
inline constexpr std::uint64_t kMarkedPixels = 4096;
inline constexpr Rgb kDiffPixel{255, 0, 255}, kDiffMarker{255, 255, 0};
RgbImage highlight_differences(const RgbImage& expected, const RgbImage& actual);

}  // namespace l2
