// PNGs made chunk by chunk (their checksums right, what they declare not), and the byte helpers
// the other hostile pictures share (issue 54). Part of hostile_pictures.hpp, which includes it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

namespace l2::hostile {

// A value's bytes as this machine holds them (little-endian here).
template <typename T>
std::string bytes_of(const T& value) {
  return std::string(reinterpret_cast<const char*>(&value), sizeof value);
}

inline std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const unsigned char b : bytes) {
    crc ^= b;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

inline std::string big_endian(std::uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
          static_cast<char>(v)};
}

inline std::string png_chunk(const std::string& type, const std::string& data) {
  return big_endian(static_cast<std::uint32_t>(data.size())) + type + data +
         big_endian(crc32(type + data));
}

// A PNG of width x height 8-bit RGB pixels (interlaced or not) whose image data is a zlib
// stream of `raw` (the filtered rows, which may hold far fewer bytes than the size claims) in
// stored blocks; `damaged`: its zlib check (Adler-32) one off, as a bit flipped in the data
// leaves it.
inline std::string png(std::uint32_t width, std::uint32_t height, bool interlaced,
                       const std::string& raw, bool damaged = false) {
  std::string idat = "\x78\x01";  // zlib, no compression
  for (std::size_t at = 0; at == 0 || at < raw.size(); at += 0xFFFF) {
    const auto n = static_cast<std::uint16_t>(std::min<std::size_t>(raw.size() - at, 0xFFFF));
    idat += at + n >= raw.size() ? '\x01' : '\x00';  // the last block or not, stored
    idat += bytes_of(n) + bytes_of(static_cast<std::uint16_t>(~n)) + raw.substr(at, n);
  }
  std::uint32_t a = 1, b = 0;  // Adler-32
  for (const unsigned char c : raw) {
    a = (a + c) % 65521;
    b = (b + a) % 65521;
  }
  idat += big_endian((b << 16 | a) ^ (damaged ? 1u : 0u));
  const std::string ihdr = big_endian(width) + big_endian(height) +
                           std::string("\x08\x02\x00\x00", 4) +
                           std::string(1, interlaced ? '\x01' : '\x00');
  return "\x89PNG\r\n\x1a\n" + png_chunk("IHDR", ihdr) + png_chunk("IDAT", idat) +
         png_chunk("IEND", "");
}

// A whole 4x2 RGB picture (not interlaced): each row a filter byte and 12 bytes of colour;
// `damaged` as for png().
inline std::string small_png(bool damaged = false) {
  std::string raw;
  for (int y = 0; y < 2; ++y) {
    raw += '\0';
    for (int x = 0; x < 4; ++x) raw += std::string{char(40 * x), char(100 * y), '\x7f'};
  }
  return png(4, 2, false, raw, damaged);
}

// small_png() with its signature's last byte changed and a byte put after it: the first chunk's
// length then reads as 0xD20A0000, beyond what PNG allows (as fuzz_picture_file found it).
inline std::string damaged_signature_png() {
  std::string p = small_png();
  p[7] = '`';
  return p.insert(8, 1, '\xD2');
}

}  // namespace l2::hostile
