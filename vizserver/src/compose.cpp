#include "compose.hpp"

#include <algorithm>
#include <cstring>

namespace l2::viz {
namespace {

constexpr std::uint32_t kFar = 0xFFFFFF;

std::uint32_t rgb_at(const std::uint8_t* p) {
  return std::uint32_t{p[0]} << 16 | std::uint32_t{p[1]} << 8 | p[2];
}

// Columns [0, n) of one clipped row: `src` colour (and for DEPTH `src_depth`) onto `dst`, whose
// depths are `depth` (nullptr: the display has no plane).
void apply_row(const TileHeader& tile, const std::uint8_t* src, const std::uint8_t* src_depth,
               std::uint8_t* dst, std::uint32_t* depth, long long n) {
  if (tile.how == TileKind::Copy) {
    std::memcpy(dst, src, static_cast<std::size_t>(n) * 3);
    if (depth) std::fill_n(depth, n, 0u);
    return;
  }
  for (long long i = 0; i < n; ++i, src += 3, dst += 3) {
    std::uint32_t d = 0;
    if (tile.how == TileKind::Key && rgb_at(src) == tile.key) continue;
    if (tile.how == TileKind::Depth) {
      d = rgb_at(src_depth + i * 3);
      if (d >= depth[i]) continue;
    }
    std::memcpy(dst, src, 3);
    if (depth) depth[i] = d;
  }
}

}  // namespace

void compose_tile(std::vector<RgbImage>& displays, std::vector<DepthPlane>& depths,
                  const TileHeader& tile, const std::uint8_t* pixels, std::size_t stride,
                  StripErrorCounts& counts) {
  if (tile.display >= displays.size()) {
    counts.missing_display += tile.h;
    return;
  }
  RgbImage& out = displays[tile.display];
  if (depths.size() < displays.size()) depths.resize(displays.size());
  DepthPlane& plane = depths[tile.display];
  if (tile.how == TileKind::Depth && plane.empty()) {
    plane.assign(static_cast<std::size_t>(out.width()) * out.height(), kFar);
  }
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
    const std::uint8_t* row = pixels + r * stride;
    const std::size_t skip = static_cast<std::size_t>(cx0 - x0) * 3;
    std::uint32_t* depth =
        plane.empty() ? nullptr : plane.data() + static_cast<std::size_t>(y) * out.width() + cx0;
    apply_row(tile, row + skip, row + std::size_t{tile.w} * 3 + skip,
              out.row(static_cast<int>(y)).data() + cx0 * 3, depth, cx1 - cx0);
  }
}

std::optional<coverage::Area> copy_area(const TileHeader& tile, int width, int height) {
  if (tile.how != TileKind::Copy || width > 0xFFFF || height > 0xFFFF) return std::nullopt;
  // 64-bit arithmetic: dx + w can pass INT_MAX for a hostile header.
  const long long x0 = std::max<long long>(tile.dx, 0);
  const long long x1 = std::min<long long>(static_cast<long long>(tile.dx) + tile.w, width);
  const long long y0 = std::max<long long>(tile.dy, 0);
  const long long y1 = std::min<long long>(static_cast<long long>(tile.dy) + tile.h, height);
  if (x0 >= x1 || y0 >= y1) return std::nullopt;
  return coverage::Area{static_cast<std::uint16_t>(y0), static_cast<std::uint16_t>(y1),
                        static_cast<std::uint16_t>(x0), static_cast<std::uint16_t>(x1), 0};
}

void fill_uncovered(RgbImage& display, const std::vector<coverage::Area>& areas, Rgb background,
                    coverage::CoverageScratch& scratch) {
  if (display.width() > 0xFFFF || display.height() > 0xFFFF) {  // beyond the sweep's 16-bit rows
    display.fill(background);
    return;
  }
  coverage::sweep_coverage(
      areas, 0, display.height(), display.width(), scratch,
      [&](int y0, int y1, const std::vector<coverage::CoverageScratch::Gap>& gaps) {
        for (const auto& g : gaps) display.fill_rect(g.x0, y0, g.x1 - g.x0, y1 - y0, background);
      });
}

void compose_tile(std::vector<RgbImage>& displays, const TileHeader& tile,
                  const std::uint8_t* pixels, std::size_t stride, StripErrorCounts& counts) {
  std::vector<DepthPlane> none;
  compose_tile(displays, none, tile, pixels, stride, counts);
}

}  // namespace l2::viz
