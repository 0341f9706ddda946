#include "image/level_map.hpp"

#include <cmath>
#include <cstddef>
#include <stdexcept>

#include <fmt/format.h>

namespace l2 {

LevelMap level_map(int width, int height, std::span<const std::uint8_t> alpha, double alpha_gamma,
                   std::span<const std::uint8_t> beta) {
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (width <= 0 || height <= 0 || (!alpha.empty() && alpha.size() != pixels) ||
      (!beta.empty() && beta.size() != pixels) || !(alpha_gamma > 0)) {
    throw std::invalid_argument(
        fmt::format("alpha of {} and beta of {} bytes at gamma {} for a {}x{} level map",
                    alpha.size(), beta.size(), alpha_gamma, width, height));
  }
  LevelMap map{width, height, std::vector<std::uint32_t>(pixels),
               std::vector<std::uint32_t>(pixels)};
  const auto fixed = [](double v) {
    return static_cast<std::uint32_t>(std::floor(v * kLevelOne + 0.5));
  };
  for (std::size_t i = 0; i < pixels; ++i) {
    const double a = alpha.empty() ? 1.0 : alpha[i] / 255.0;
    const double b = beta.empty() ? 0.0 : beta[i] / 255.0;
    map.gain[i] = fixed(std::pow(a, 1 / alpha_gamma) * (1 - b));
    map.offset[i] = fixed(b * 255);
  }
  return map;
}

bool is_identity(const LevelMap& map) {
  for (std::size_t i = 0; i < map.gain.size(); ++i)
    if (map.gain[i] != kLevelOne || map.offset[i] != 0) return false;
  return true;
}

void apply_level_map(const LevelMap& map, const RgbImage& in, RgbImage& out) {
  if (in.width() != map.width || in.height() != map.height) {
    throw std::invalid_argument(fmt::format("a {}x{} picture through a {}x{} level map", in.width(),
                                            in.height(), map.width, map.height));
  }
  if (&in != &out && (out.width() != in.width() || out.height() != in.height()))
    out = RgbImage::unfilled(in.width(), in.height());
  // Every display pixel of every frame passes here: a multiply and an add per byte, no call or
  // branch. gain * 255 + offset stays within 255.5 * kLevelOne, so the result is a byte.
  const std::uint32_t* gain = map.gain.data();
  const std::uint32_t* offset = map.offset.data();
  const std::uint8_t* src = in.data();
  std::uint8_t* dst = out.data();
  const std::size_t pixels = static_cast<std::size_t>(in.width()) * in.height();
  for (std::size_t i = 0; i < pixels; ++i, src += 3, dst += 3) {
    const std::uint32_t g = gain[i], o = offset[i] + kLevelOne / 2;
    dst[0] = static_cast<std::uint8_t>((src[0] * g + o) >> 16);
    dst[1] = static_cast<std::uint8_t>((src[1] * g + o) >> 16);
    dst[2] = static_cast<std::uint8_t>((src[2] * g + o) >> 16);
  }
}

}  // namespace l2
