#include "image/colour_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace l2 {

ColourTable ColourTable::identity() {
  ColourTable t;
  for (auto& c : t.channel)
    for (int i = 0; i < 256; ++i) c[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i);
  return t;
}

bool ColourTable::is_identity() const {
  return *this == identity();
}

ColourTable colour_table_from_gain(const std::array<double, 3>& gain,
                                   const std::array<int, 3>& offset) {
  ColourTable t;
  for (std::size_t c = 0; c < t.channel.size(); ++c) {
    // Integers from here on: 255 * kMaxGain * 2^32 fits an int64 many times over.
    const auto g = static_cast<std::int64_t>(std::llround(std::ldexp(gain[c], kGainShift)));
    constexpr std::int64_t kHalf = std::int64_t{1} << (kGainShift - 1);
    for (std::int64_t in = 0; in < 256; ++in) {
      const std::int64_t scaled = (in * g + kHalf) >> kGainShift;  // both >= 0: floor
      const std::int64_t out = std::clamp<std::int64_t>(scaled + offset[c], 0, 255);
      t.channel[c][static_cast<std::size_t>(in)] = static_cast<std::uint8_t>(out);
    }
  }
  return t;
}

ColourTable compose(const ColourTable& first, const ColourTable& then) {
  ColourTable t;
  for (std::size_t c = 0; c < t.channel.size(); ++c)
    for (std::size_t i = 0; i < 256; ++i) t.channel[c][i] = then.channel[c][first.channel[c][i]];
  return t;
}

void apply_colour(const ColourTable& table, const RgbImage& in, RgbImage& out) {
  if (&in != &out && (out.width() != in.width() || out.height() != in.height()))
    out = RgbImage::unfilled(in.width(), in.height());
  // One lookup per byte, three tables in turn: every display pixel of every frame passes here,
  // so no call or branch per pixel.
  const ColourTable::Channel& r = table.channel[0];
  const ColourTable::Channel& g = table.channel[1];
  const ColourTable::Channel& b = table.channel[2];
  const std::uint8_t* src = in.data();
  std::uint8_t* dst = out.data();
  const std::size_t pixels = static_cast<std::size_t>(in.width()) * in.height();
  for (std::size_t i = 0; i < pixels; ++i, src += 3, dst += 3) {
    dst[0] = r[src[0]];
    dst[1] = g[src[1]];
    dst[2] = b[src[2]];
  }
}

}  // namespace l2
