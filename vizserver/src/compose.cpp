#include "vizserver/compose.hpp"

#include <algorithm>
#include <cstring>

namespace l2::viz {

void compose_tile(std::vector<RgbImage>& displays, const TileHeader& tile,
                  const std::uint8_t* pixels, std::size_t stride, StripErrorCounts& counts) {
  if (tile.display >= displays.size()) {
    counts.missing_display += tile.h;
    return;
  }
  RgbImage& out = displays[tile.display];
  // 64-bit arithmetic: dx + w can pass INT_MAX for a hostile header.
  const long long x0 = tile.dx, x1 = x0 + tile.w;
  const long long cx0 = std::max(x0, 0LL), cx1 = std::min<long long>(x1, out.width());
  const bool columns_inside = cx0 == x0 && cx1 == x1;
  for (std::uint32_t r = 0; r < tile.h; ++r) {
    const long long y = static_cast<long long>(tile.dy) + r;
    if (y < 0 || y >= out.height() || cx1 <= cx0) {
      ++counts.clips;
      continue;
    }
    if (!columns_inside) ++counts.clips;
    const std::uint8_t* src = pixels + r * stride + static_cast<std::size_t>(cx0 - x0) * 3;
    std::memcpy(out.row(static_cast<int>(y)).data() + cx0 * 3, src,
                static_cast<std::size_t>(cx1 - cx0) * 3);
  }
}

}  // namespace l2::viz
