// Test helper: a scanline built by hand (headers, extension words and strip pixels placed at
// chosen columns, RGB or RGBA) and the parser's findings on it.
#pragma once

#include <ostream>
#include <vector>

#include "strip_headers/scanline_parser.hpp"

namespace l2 {
// Failures name the counts rather than dumping their bytes.
inline void PrintTo(const StripErrorCounts& c, std::ostream* os) {
  *os << "{check " << c.check_errors << ", EXT unsupported " << c.ext_unsupported << ", zero width "
      << c.zero_width << ", truncations " << c.truncations << ", missing " << c.missing_display
      << ", clips " << c.clips << "}";
}
}  // namespace l2

namespace l2::testing {

struct Row {
  int bpp;
  std::vector<std::uint8_t> bytes;
  Row(int width, int bytes_per_pixel)
      : bpp(bytes_per_pixel), bytes(static_cast<std::size_t>(width) * bytes_per_pixel, 0) {}
  int width() const { return static_cast<int>(bytes.size()) / bpp; }
  // A 48-bit value (header or extension word) in the two pixels at x.
  void header(int x, std::uint64_t value) { write_header_pixels(value, &bytes[x * bpp], bpp); }
  void header(int x, const StripHeader& h) { header(x, encode(h)); }
  // An EXT header at x and its extension word at x + 2.
  void ext(int x, const StripHeader& h, std::uint64_t word) {
    header(x, h);
    header(x + 2, word);
  }
};

struct Parsed {
  std::vector<ParsedStrip> strips;
  StripErrorCounts errors;
};

inline Parsed parse(const Row& row) {
  Parsed out;
  parse_scanline(row.bytes.data(), row.width(), row.bpp, out.errors,
                 [&](const ParsedStrip& s) { out.strips.push_back(s); });
  return out;
}

inline StripErrorCounts counts(std::uint64_t check, std::uint64_t ext, std::uint64_t zero,
                               std::uint64_t trunc) {
  StripErrorCounts c;
  c.check_errors = check;
  c.ext_unsupported = ext;
  c.zero_width = zero;
  c.truncations = trunc;
  return c;
}

}  // namespace l2::testing
