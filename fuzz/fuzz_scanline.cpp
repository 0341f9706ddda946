// The scanline parser (spec §3) on arbitrary rows: the first byte picks RGB or RGBA, the rest is
// the row, copied into a buffer of exactly its size so that any read past it is caught.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fuzz_check.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "strip_headers/strip_header.hpp"

using l2::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const int bytes_per_pixel = (data[0] & 1) ? 4 : 3;
  const int width = static_cast<int>((size - 1) / static_cast<std::size_t>(bytes_per_pixel));
  const std::vector<std::uint8_t> row(data + 1,
                                      data + 1 + static_cast<std::size_t>(width) * bytes_per_pixel);
  l2::StripErrorCounts errors;
  int seen = 0, next_x = l2::kHeaderPixels;
  const int strips =
      l2::parse_scanline(row.data(), width, bytes_per_pixel, errors, [&](const l2::ParsedStrip& s) {
        ++seen;
        require(s.source_x >= next_x, "strips come in scan order, each after its header");
        // A header at the very end of the row leaves 0 pixels: a truncated strip, counted.
        require(s.length >= 0 && s.length <= s.header.width, "a strip has 0..width pixels");
        require(s.source_x + s.length <= width, "a strip ends inside the row");
        // Its header stands before its gap: two columns, four for EXT with its extension word.
        require(l2::encode(s.header) ==
                    l2::header_value(row.data() + s.header_x() * bytes_per_pixel,
                                     row.data() + (s.header_x() + 1) * bytes_per_pixel),
                "a strip's header encodes back to the bits it was read from");
        next_x = s.next_header_x() + l2::kHeaderPixels;
      });
  require(strips == seen, "the count returned is the strips handed over");
  require(errors.truncations <= 1, "a truncated strip is the scanline's last");
  require(errors.total() <= 1, "a scanline stops at its first error");
  return 0;
}
