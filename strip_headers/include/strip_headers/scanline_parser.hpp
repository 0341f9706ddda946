// Spec §3 and §7: walks one scanline header by header and hands every COPY, SKIP, KEY and DEPTH
// strip to a callback. Works in place on RGB or RGBA rows, allocates nothing, and never reads
// outside the row, whatever the bytes are — it is the emulator's hot path and its first line of
// defence.
#pragma once

#include <algorithm>
#include <cstdint>
#include <type_traits>

#include "strip_headers/extension_word.hpp"
#include "strip_headers/strip_header.hpp"

namespace l2 {

// Every error kind of spec §3 and §7, counted separately. The parser fills the first four; the
// router fills the last two because only it knows the mesh and the display sizes.
struct StripErrorCounts {
  std::uint64_t check_errors = 0;     // a header's or an extension word's check did not match
  std::uint64_t ext_unsupported = 0;  // extension word of no known kind or with must-be-0 bits
  std::uint64_t zero_width = 0;       // COPY/SKIP/EXT with width 0: rest of scanline dropped
  std::uint64_t truncations = 0;      // strip or extension word ran past the end of the scanline
  std::uint64_t missing_display = 0;  // strip to a display the mesh does not have
  std::uint64_t clips = 0;            // strip landing partly or wholly outside its display

  StripErrorCounts& operator+=(const StripErrorCounts& o);
  std::uint64_t total() const;
  friend bool operator==(const StripErrorCounts&, const StripErrorCounts&) = default;
};

// One strip found on a scanline: COPY or SKIP (header.op), or EXT with its extension word.
struct ParsedStrip {
  StripHeader header;
  int source_x = 0;       // column of the strip's first colour pixel in the scanline
  int length = 0;         // colour pixels to route: header.width unless truncated
  Extension extension{};  // EXT only: KEY (with its key colour) or DEPTH

  bool is(ExtKind kind) const { return header.op == StripOp::Ext && extension.kind == kind; }
  // Column of the header: before the strip's two-pixel gap, or four for EXT (§7).
  int header_x() const {
    return source_x - kHeaderPixels - (header.op == StripOp::Ext ? kExtensionPixels : 0);
  }
  // DEPTH: column of depth pixel 0; depth pixel i, for i < length, is at depth_x() + i.
  int depth_x() const { return source_x + header.width; }
  // Where the next header starts: after width colour pixels, and for DEPTH width depth pixels.
  int next_header_x() const { return source_x + header.width * (is(ExtKind::Depth) ? 2 : 1); }
};

namespace parser_detail {

// Reads the extension word after an EXT header at the row's pixel `header`, of which
// `pixels_left` remain, in the order of §7's error table. Returns false, with the error counted,
// when the scanline ends here; else moves `strip` past the word.
inline bool read_extension(const std::uint8_t* header, int pixels_left, int bytes_per_pixel,
                           ParsedStrip& strip, StripErrorCounts& errors) {
  if (pixels_left < kHeaderPixels + kExtensionPixels) {
    ++errors.truncations;
    return false;
  }
  const std::uint8_t* word = header + kHeaderPixels * bytes_per_pixel;
  const DecodedExtension d = decode_extension(header_value(word, word + bytes_per_pixel));
  if (d.status == ExtensionStatus::CheckError) {
    ++errors.check_errors;
    return false;
  }
  if (d.status == ExtensionStatus::Unsupported) {
    ++errors.ext_unsupported;
    return false;
  }
  strip.extension = d.extension;
  strip.source_x += kExtensionPixels;
  return true;
}

// The colour pixels of a strip to route when its payload runs past the row: for DEPTH, only
// those whose depth pixel exists (§7).
inline int routable_length(const ParsedStrip& s, int width_px) {
  const int width = s.header.width;
  const int depth_pixels = s.is(ExtKind::Depth) ? width : 0;
  return std::min(width, std::max(0, width_px - s.source_x - depth_pixels));
}

// Calls on_strip; a callback that returns bool ends the scanline by returning false.
template <class OnStrip>
bool hand_over(OnStrip& on_strip, const ParsedStrip& s) {
  if constexpr (std::is_same_v<std::invoke_result_t<OnStrip&, const ParsedStrip&>, bool>) {
    return on_strip(s);
  } else {
    on_strip(s);
    return true;
  }
}

}  // namespace parser_detail

// Parses `row` (width_px pixels of bytes_per_pixel bytes, R G B first). Calls
// on_strip(const ParsedStrip&) for each COPY, SKIP, KEY and DEPTH, in scan order, and adds the
// scanline's parser errors to `errors`. A callback may return bool: false drops the rest of
// the scanline (a caller that does not composite treats EXT as §3 says). Returns the number of
// strips handed over.
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
    ParsedStrip s{*header, x + kHeaderPixels, 0};
    if (header->op == StripOp::Ext &&
        !parser_detail::read_extension(p, width_px - x, bytes_per_pixel, s, errors)) {
      break;
    }
    if (header->width == 0) {
      ++errors.zero_width;
      break;
    }
    s.length = parser_detail::routable_length(s, width_px);
    ++strips;
    if (!parser_detail::hand_over(on_strip, s)) break;
    x = s.next_header_x();
    if (x > width_px) {
      ++errors.truncations;
      break;
    }
  }
  return strips;
}

}  // namespace l2
