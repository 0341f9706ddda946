#include "display_compare.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

namespace l2 {

DisplayDiff compare_displays(const RgbImage& a, const RgbImage& b) {
  DisplayDiff diff;
  if (a.width() != b.width() || a.height() != b.height()) {
    const int w = std::max(a.width(), b.width()), h = std::max(a.height(), b.height());
    diff.differing_pixels = static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h);
    diff.beyond_one = diff.differing_pixels;
    diff.largest = 255;
    diff.largest_x = diff.largest_y = 0;
    diff.size_differs = true;
    diff.picture = RgbImage(std::max(w, 1), std::max(h, 1), Rgb{255, 255, 255});
    return diff;
  }
  diff.picture = RgbImage(a.width(), a.height());
  for (int y = 0; y < a.height(); ++y) {
    const auto ra = a.row(y), rb = b.row(y);
    if (std::memcmp(ra.data(), rb.data(), ra.size()) == 0) continue;  // the common case
    auto out = diff.picture.row(y);
    for (std::size_t x = 0; x < ra.size(); x += 3) {
      int largest = 0;
      for (std::size_t c = 0; c < 3; ++c) {
        const int d = std::abs(int{ra[x + c]} - int{rb[x + c]});
        // Even a difference of one shows in the picture.
        out[x + c] = static_cast<std::uint8_t>(d == 0 ? 0 : std::max(d, 64));
        largest = std::max(largest, d);
      }
      if (largest == 0) continue;
      ++diff.differing_pixels;
      if (largest > 1) ++diff.beyond_one;
      if (largest > diff.largest) {
        diff.largest = largest;
        diff.largest_x = static_cast<int>(x / 3);
        diff.largest_y = y;
      }
    }
  }
  return diff;
}

namespace {

RgbImage dimmed(const RgbImage& image) {
  RgbImage out = image;
  for (int y = 0; y < out.height(); ++y) {
    for (std::uint8_t& v : out.row(y)) v = static_cast<std::uint8_t>(v / 4);
  }
  return out;
}

bool pixel_differs(const RgbImage& a, const RgbImage& b, int x, int y) {
  return std::memcmp(a.row(y).data() + x * 3, b.row(y).data() + x * 3, 3) != 0;
}

// The outline of a square of side 2r+1 around (cx, cy), clipped to the picture: 13 pixels
// wide, wider on large pictures so it still shows when they are viewed scaled down.
void draw_marker(RgbImage& picture, int cx, int cy) {
  const int r = std::max(6, std::max(picture.width(), picture.height()) / 128);
  for (int i = -r; i <= r; ++i) {
    for (const auto& [x, y] : {std::pair{cx + i, cy - r}, std::pair{cx + i, cy + r},
                               std::pair{cx - r, cy + i}, std::pair{cx + r, cy + i}}) {
      if (x >= 0 && y >= 0 && x < picture.width() && y < picture.height()) {
        picture.set(x, y, kDiffMarker);
      }
    }
  }
}

}  // namespace

RgbImage highlight_differences(const RgbImage& expected, const RgbImage& actual) {
  RgbImage picture = dimmed(actual);
  if (expected.width() != actual.width() || expected.height() != actual.height()) {
    const int w = picture.width(), h = picture.height();
    for (int t = 0; t < 4; ++t) {
      picture.fill_rect(0, t, w, 1, kDiffPixel);
      picture.fill_rect(0, h - 1 - t, w, 1, kDiffPixel);
      picture.fill_rect(t, 0, 1, h, kDiffPixel);
      picture.fill_rect(w - 1 - t, 0, 1, h, kDiffPixel);
    }
    return picture;
  }
  std::vector<std::pair<int, int>> differing;
  for (int y = 0; y < actual.height(); ++y) {
    if (std::memcmp(expected.row(y).data(), actual.row(y).data(), actual.stride()) == 0) continue;
    for (int x = 0; x < actual.width(); ++x) {
      if (pixel_differs(expected, actual, x, y)) differing.emplace_back(x, y);
    }
  }
  // Markers first, so a differing pixel is never covered by a neighbour's marker.
  if (differing.size() <= kMarkedPixels) {
    for (const auto& [x, y] : differing) draw_marker(picture, x, y);
  }
  for (const auto& [x, y] : differing) picture.set(x, y, kDiffPixel);
  return picture;
}

}  // namespace l2
