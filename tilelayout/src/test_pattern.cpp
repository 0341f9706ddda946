#include "tilelayout/test_pattern.hpp"

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

}  // namespace l2
