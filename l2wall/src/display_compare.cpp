#include "display_compare.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace l2 {

DisplayDiff compare_displays(const RgbImage& a, const RgbImage& b) {
  DisplayDiff diff;
  if (a.width() != b.width() || a.height() != b.height()) {
    const int w = std::max(a.width(), b.width()), h = std::max(a.height(), b.height());
    diff.differing_pixels = static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h);
    diff.picture = RgbImage(std::max(w, 1), std::max(h, 1), Rgb{255, 255, 255});
    return diff;
  }
  diff.picture = RgbImage(a.width(), a.height());
  for (int y = 0; y < a.height(); ++y) {
    const auto ra = a.row(y), rb = b.row(y);
    if (std::memcmp(ra.data(), rb.data(), ra.size()) == 0) continue;  // the common case
    auto out = diff.picture.row(y);
    for (std::size_t x = 0; x < ra.size(); x += 3) {
      bool differs = false;
      for (std::size_t c = 0; c < 3; ++c) {
        const int d = std::abs(int{ra[x + c]} - int{rb[x + c]});
        // Even a difference of one shows in the picture.
        out[x + c] = static_cast<std::uint8_t>(d == 0 ? 0 : std::max(d, 64));
        differs = differs || d != 0;
      }
      if (differs) ++diff.differing_pixels;
    }
  }
  return diff;
}

}  // namespace l2
