#include "image/table_map.hpp"

#include <cstddef>
#include <stdexcept>

#include <fmt/format.h>

namespace l2 {

void apply_table_map(const TableMap& map, const RgbImage& in, RgbImage& out) {
  if (in.width() != map.width || in.height() != map.height) {
    throw std::invalid_argument(fmt::format("a {}x{} picture through a {}x{} table map", in.width(),
                                            in.height(), map.width, map.height));
  }
  if (&in != &out && (out.width() != in.width() || out.height() != in.height()))
    out = RgbImage::unfilled(in.width(), in.height());
  // Every display pixel of every frame passes here: one index and three lookups per pixel, no
  // call or branch.
  const ColourTable* tables = map.tables.data();
  const std::uint16_t* index = map.index.data();
  const std::uint8_t* src = in.data();
  std::uint8_t* dst = out.data();
  const std::size_t pixels = static_cast<std::size_t>(in.width()) * in.height();
  for (std::size_t i = 0; i < pixels; ++i, src += 3, dst += 3) {
    const ColourTable& t = tables[index[i]];
    dst[0] = t.channel[0][src[0]];
    dst[1] = t.channel[1][src[1]];
    dst[2] = t.channel[2][src[2]];
  }
}

}  // namespace l2
