// Spec §3: walks one scanline header by header and hands every COPY and SKIP strip to a
// callback. Works in place on RGB or RGBA rows, allocates nothing, and never reads outside the
// row, whatever the bytes are — it is the emulator's hot path and its first line of defence.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>

#include "strip_headers/strip_header.hpp"

namespace l2 {

// Every error kind of spec §3, counted separately. The parser fills the first four; the router
// fills the last two because only it knows the mesh and the display sizes.
struct StripErrorCounts {
  std::uint64_t check_errors = 0;     // check bits did not match: rest of scanline dropped
  std::uint64_t ext_unsupported = 0;  // EXT header: rest of scanline dropped
  std::uint64_t zero_width = 0;       // COPY/SKIP with width 0: rest of scanline dropped
  std::uint64_t truncations = 0;      // strip ran past the end of the scanline
  std::uint64_t missing_display = 0;  // COPY to a display the mesh does not have
  std::uint64_t clips = 0;            // COPY landing partly or wholly outside its display

  StripErrorCounts& operator+=(const StripErrorCounts& o);
  std::uint64_t total() const;
  friend bool operator==(const StripErrorCounts&, const StripErrorCounts&) = default;
};

// One COPY or SKIP strip found on a scanline.
struct ParsedStrip {
  StripHeader header;
  int source_x = 0;  // column of the strip's first pixel in the scanline
  int length = 0;    // pixels present in the scanline: header.width unless truncated
};

// Parses `row` (width_px pixels of bytes_per_pixel bytes, R G B first). Calls
// on_strip(const ParsedStrip&) for each COPY and SKIP, in scan order, and adds the scanline's
// parser errors to `errors`. Returns the number of strips handed over.
template <class OnStrip>
int parse_scanline(const std::uint8_t* row, int width_px, int bytes_per_pixel,
                   StripErrorCounts& errors, OnStrip&& on_strip) {
  int strips = 0;
  int x = 0;
  while (width_px - x >= kHeaderPixels) {
    const std::uint8_t* p = row + static_cast<std::ptrdiff_t>(x) * bytes_per_pixel;
    const auto header = decode(header_value(p, p + bytes_per_pixel));
    if (!header) {
      ++errors.check_errors;
      break;
    }
    if (header->op == StripOp::End) break;
    if (header->op == StripOp::Ext) {
      ++errors.ext_unsupported;
      break;
    }
    if (header->width == 0) {
      ++errors.zero_width;
      break;
    }
    const int source_x = x + kHeaderPixels;
    const int length = std::min<int>(header->width, width_px - source_x);
    on_strip(ParsedStrip{*header, source_x, length});
    ++strips;
    if (length < header->width) {
      ++errors.truncations;
      break;
    }
    x = source_x + header->width;
  }
  return strips;
}

}  // namespace l2
