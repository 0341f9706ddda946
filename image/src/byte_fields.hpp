// Unsigned fields of `n` bytes (at most 4) from a header's bytes, little- or big-endian; bytes
// past the end read as 0, so a header cut short never reads outside its string.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace l2::png_codec {

inline std::uint32_t le(std::string_view b, std::size_t at, int n) {
  std::uint32_t v = 0;
  for (int i = 0; i < n && at + i < b.size(); ++i)
    v |= std::uint32_t{static_cast<unsigned char>(b[at + i])} << (8 * i);
  return v;
}

inline std::uint32_t be(std::string_view b, std::size_t at, int n) {
  std::uint32_t v = 0;
  for (int i = 0; i < n; ++i)
    v = v << 8 | (at + i < b.size() ? static_cast<unsigned char>(b[at + i]) : 0u);
  return v;
}

}  // namespace l2::png_codec
