#include "tilelayout/test_pattern.hpp"

#include <algorithm>

#include "strip_headers/strip_header.hpp"

namespace l2 {
namespace {
constexpr unsigned kMask24 = 0xFFFFFF;
constexpr unsigned kMultiplier = 0x5BD1E9;  // odd, so d+1 -> mask is one-to-one mod 2^24
}  // namespace

unsigned test_pattern_mask(int display) {
  return (static_cast<unsigned>(display + 1) * kMultiplier) & kMask24;
}

Rgb test_pattern(int display, int x, int y) {
  const unsigned v = (static_cast<unsigned>(x) & 0xFFF) << 12 | (static_cast<unsigned>(y) & 0xFFF);
  const unsigned c = v ^ test_pattern_mask(display);
  return {static_cast<std::uint8_t>(c >> 16), static_cast<std::uint8_t>(c >> 8 & 0xFF),
          static_cast<std::uint8_t>(c & 0xFF)};
}

std::optional<std::pair<int, int>> test_pattern_position(int display, Rgb colour) {
  if (display < 0 || display >= kMaxDisplays) return std::nullopt;
  const unsigned c = unsigned{colour.r} << 16 | unsigned{colour.g} << 8 | unsigned{colour.b};
  const unsigned v = c ^ test_pattern_mask(display);
  return std::pair<int, int>{static_cast<int>(v >> 12), static_cast<int>(v & 0xFFF)};
}

namespace {
// A well-mixed 32-bit hash of a display pixel (the finaliser of MurmurHash3).
std::uint32_t pixel_hash(int display, int x, int y) {
  std::uint32_t h = static_cast<std::uint32_t>(display) * 0x9E3779B9u ^
                    static_cast<std::uint32_t>(x) * 0x85EBCA6Bu ^
                    static_cast<std::uint32_t>(y) * 0xC2B2AE35u;
  h ^= h >> 16;
  h *= 0x85EBCA6Bu;
  h ^= h >> 13;
  h *= 0xC2B2AE35u;
  h ^= h >> 16;
  return h;
}
}  // namespace

LayerPixel depth_test_pixel(int display, int x, int y, int layer, int layers) {
  const std::uint32_t h = pixel_hash(display, x, y);
  const int winner = static_cast<int>(h % static_cast<std::uint32_t>(std::max(layers, 1)));
  const std::uint32_t base = 1 + (h >> 8) % 0xFFEFFF;  // room above for every loser's depth
  const Rgb right = test_pattern(display, x, y);
  if (layer == winner) return {right, base};
  const Rgb wrong{static_cast<std::uint8_t>(right.r ^ 0x80), right.g, right.b};
  const std::uint32_t farther = base + 1 + static_cast<std::uint32_t>(layer);
  if (layer < winner) return {wrong, (h >> 4 & 3) == 0 ? 0xFFFFFFu : farther};
  return {wrong, (h >> 6 & 1) != 0 ? base : farther};
}

bool key_test_transparent(int x, int y) {
  return ((x >> 2) + (y >> 2)) % 2 == 0;
}

}  // namespace l2
