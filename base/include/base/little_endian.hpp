// Integers as the project's wire formats carry them, least significant byte first, whatever
// the machine: put_u32(p, 0x5A56324C) writes the bytes 4C 32 56 5A, and get_u32 reads them
// back. Header-only; the one implementation every message format uses.
//
// Example:
//
//   std::uint8_t header[8];
//   l2::put_u32(header, 0x5A56324C);  // 4C 32 56 5A
//   l2::put_u16(header + 4, 1);       // 01 00
//   const std::uint32_t magic = l2::get_u32(header);      // 0x5A56324C
//   const std::uint16_t version = l2::get_u16(header + 4);  // 1
#pragma once

#include <cstdint>

namespace l2 {

inline void put_u16(std::uint8_t* p, std::uint16_t v) {
  p[0] = static_cast<std::uint8_t>(v);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
inline void put_u32(std::uint8_t* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
inline std::uint16_t get_u16(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
inline std::uint32_t get_u32(const std::uint8_t* p) {
  return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 |
         std::uint32_t{p[3]} << 24;
}

}  // namespace l2
