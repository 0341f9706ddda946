#include "scaled_picture.hpp"

namespace l2 {

RgbImage every_nth_pixel(const RgbImage& picture, int n) {
  RgbImage small((picture.width() + n - 1) / n, (picture.height() + n - 1) / n);
  for (int y = 0; y < small.height(); ++y) {
    const std::uint8_t* from = picture.row(y * n).data();
    std::uint8_t* to = small.row(y).data();
    for (int x = 0; x < small.width(); ++x) {
      const std::uint8_t* p = from + static_cast<std::size_t>(x) * n * RgbImage::kChannels;
      to[0] = p[0];
      to[1] = p[1];
      to[2] = p[2];
      to += RgbImage::kChannels;
    }
  }
  return small;
}

}  // namespace l2
