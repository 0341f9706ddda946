// resample_grey: bilinear resampling of a one-byte-a-pixel map, worked in double.
#include "image/grey_resample.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace l2 {
namespace {

// Where output index i of `out` samples an input of `in` pixels: the lower input pixel and the
// weight of the next one.
struct Tap {
  int lower = 0, upper = 0;
  double fraction = 0;
};

Tap tap(int i, int in, int out) {
  const double at = std::clamp((i + 0.5) * in / out - 0.5, 0.0, static_cast<double>(in - 1));
  Tap t;
  t.lower = static_cast<int>(std::floor(at));
  t.upper = std::min(t.lower + 1, in - 1);
  t.fraction = at - t.lower;
  return t;
}

}  // namespace

std::vector<std::uint8_t> resample_grey(std::span<const std::uint8_t> in, int in_width,
                                        int in_height, int out_width, int out_height) {
  if (in_width < 1 || in_height < 1 || out_width < 1 || out_height < 1 ||
      in.size() != static_cast<std::size_t>(in_width) * in_height)
    throw std::invalid_argument("resample_grey: the map is not in_width x in_height bytes");
  const auto pixel = [&](int x, int y) {
    return static_cast<double>(in[static_cast<std::size_t>(y) * in_width + x]);
  };
  std::vector<std::uint8_t> out(static_cast<std::size_t>(out_width) * out_height);
  for (int y = 0; y < out_height; ++y) {
    const Tap ty = tap(y, in_height, out_height);
    for (int x = 0; x < out_width; ++x) {
      const Tap tx = tap(x, in_width, out_width);
      const double top =
          pixel(tx.lower, ty.lower) * (1 - tx.fraction) + pixel(tx.upper, ty.lower) * tx.fraction;
      const double bottom =
          pixel(tx.lower, ty.upper) * (1 - tx.fraction) + pixel(tx.upper, ty.upper) * tx.fraction;
      const double v = top * (1 - ty.fraction) + bottom * ty.fraction;
      out[static_cast<std::size_t>(y) * out_width + x] =
          static_cast<std::uint8_t>(std::clamp(std::floor(v + 0.5), 0.0, 255.0));
    }
  }
  return out;
}

}  // namespace l2
