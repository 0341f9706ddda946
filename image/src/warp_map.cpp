#include "image/warp_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include <fmt/format.h>

namespace l2 {
namespace {

// One normalised coordinate of a frame `size` pixels across, in 1/kWarpOne pixel from the first
// pixel's centre, clamped to the edge pixels' centres. Worked in double from the file's float: a
// position written as a pixel centre, (i + 1/2) / size, comes out as exactly i * kWarpOne.
std::int32_t warp_fixed(double normalised, int size) {
  const double pixels = normalised * size - 0.5;
  const double at = std::floor(pixels * kWarpOne + 0.5);
  return static_cast<std::int32_t>(std::clamp(at, 0.0, static_cast<double>(size - 1) * kWarpOne));
}

bool on_frame(double v) {
  return v >= 0.0 && v <= 1.0;
}  // false for NaN too

// Where output pixel `i` of `size` falls on a grid of `points` spread over the pixels' centres:
// the point before it and the fraction of the way to the next. Exact in integers, so that a grid
// the output's size puts every pixel on its own point with fraction 0.
struct GridStep {
  int point;
  double fraction;
};
GridStep grid_step(int i, int size, int points) {
  if (size == 1) return {0, 0.0};
  const long long scaled = static_cast<long long>(i) * (points - 1);
  return {static_cast<int>(scaled / (size - 1)),
          static_cast<double>(scaled % (size - 1)) / (size - 1)};
}

}  // namespace

WarpMap warp_map_from_positions(int width, int height, int grid_width, int grid_height,
                                std::span<const float> positions) {
  const auto fits = [](int grid, int size) {
    return grid >= 1 && grid <= size && (grid > 1 || size == 1);
  };
  const std::size_t points = static_cast<std::size_t>(std::max(grid_width, 0)) *
                             static_cast<std::size_t>(std::max(grid_height, 0));
  if (width <= 0 || height <= 0 || !fits(grid_width, width) || !fits(grid_height, height) ||
      positions.size() != 2 * points) {
    throw std::invalid_argument(fmt::format("{} warp positions on a {}x{} grid for a {}x{} map",
                                            positions.size(), grid_width, grid_height, width,
                                            height));
  }
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  WarpMap map{width, height, std::vector<std::int32_t>(2 * pixels)};
  // Coordinate c (0: x, 1: y) of grid point (gx, gy).
  const auto at = [&](int gx, int gy, int c) {
    return static_cast<double>(positions[2 * (static_cast<std::size_t>(gy) * grid_width + gx) + c]);
  };
  std::size_t i = 0;
  for (int y = 0; y < height; ++y) {
    const GridStep sy = grid_step(y, height, grid_height);
    for (int x = 0; x < width; ++x, ++i) {
      const GridStep sx = grid_step(x, width, grid_width);
      // The four points around it, a point of weight 0 left out: it may be past the grid's
      // edge, or NaN where this pixel's own point is not.
      double p[2];
      for (int c = 0; c < 2; ++c) {
        const auto row = [&](int gy) {
          const double left = at(sx.point, gy, c);
          return sx.fraction == 0
                     ? left
                     : left * (1 - sx.fraction) + at(sx.point + 1, gy, c) * sx.fraction;
        };
        const double top = row(sy.point);
        p[c] = sy.fraction == 0 ? top : top * (1 - sy.fraction) + row(sy.point + 1) * sy.fraction;
      }
      if (!on_frame(p[0]) || !on_frame(p[1])) {
        map.source[2 * i] = kWarpBlack;
        map.source[2 * i + 1] = 0;
        continue;
      }
      map.source[2 * i] = warp_fixed(p[0], width);
      map.source[2 * i + 1] = warp_fixed(p[1], height);
    }
  }
  return map;
}

bool is_identity(const WarpMap& map) {
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const std::size_t i = 2 * (static_cast<std::size_t>(y) * map.width + x);
      if (map.source[i] != x * kWarpOne || map.source[i + 1] != y * kWarpOne) return false;
    }
  }
  return true;
}

void apply_warp(const WarpMap& map, const RgbImage& in, RgbImage& out) {
  if (in.width() != map.width || in.height() != map.height) {
    throw std::invalid_argument(fmt::format("a {}x{} picture through a {}x{} warp", in.width(),
                                            in.height(), map.width, map.height));
  }
  if (&in == &out) throw std::invalid_argument("a warp cannot write the picture it reads");
  if (out.width() != in.width() || out.height() != in.height())
    out = RgbImage::unfilled(in.width(), in.height());
  // Every display pixel of every frame passes here: four source pixels mixed in integers, no
  // call; the only branch is black. A position on a pixel's centre has fraction 0 and reads
  // no neighbour, so the last column and row never read past the picture.
  const std::size_t stride = in.stride();
  const std::uint8_t* src = in.data();
  const std::int32_t* source = map.source.data();
  constexpr std::uint32_t kOne = kWarpOne, kHalf = 1u << 15;
  for (int y = 0; y < map.height; ++y) {
    std::uint8_t* dst = out.row(y).data();
    for (int x = 0; x < map.width; ++x, source += 2, dst += 3) {
      if (source[0] == kWarpBlack) {
        dst[0] = dst[1] = dst[2] = 0;
        continue;
      }
      const auto sx = static_cast<std::uint32_t>(source[0]);
      const auto sy = static_cast<std::uint32_t>(source[1]);
      const std::uint32_t fx = sx & (kOne - 1), fy = sy & (kOne - 1);
      // The bilinear mix as one weight per source pixel: the same sum as mixing across x
      // first, so the same bytes, in fewer multiplies.
      const std::uint32_t w00 = (kOne - fx) * (kOne - fy), w10 = fx * (kOne - fy),
                          w01 = (kOne - fx) * fy, w11 = fx * fy;
      const std::uint8_t* p00 = src + (sy >> 8) * stride + (sx >> 8) * 3;
      const std::uint8_t* p10 = p00 + (fx != 0) * 3;
      const std::uint8_t* p01 = p00 + (fy != 0) * stride;
      const std::uint8_t* p11 = p01 + (fx != 0) * 3;
      dst[0] = static_cast<std::uint8_t>(
          (p00[0] * w00 + p10[0] * w10 + p01[0] * w01 + p11[0] * w11 + kHalf) >> 16);
      dst[1] = static_cast<std::uint8_t>(
          (p00[1] * w00 + p10[1] * w10 + p01[1] * w01 + p11[1] * w11 + kHalf) >> 16);
      dst[2] = static_cast<std::uint8_t>(
          (p00[2] * w00 + p10[2] * w10 + p01[2] * w01 + p11[2] * w11 + kHalf) >> 16);
    }
  }
}

}  // namespace l2
