// Text that came from input (a wall's name, a key, a file name, a peer's message) as it may be
// printed on a terminal.
//
// Example:
//
//   fmt::print("wall: {}\n", l2::printable(wall.name));  // ESC [ 2 J prints as \x1b[2J
//   throw LayoutError(l2::printable(fmt::format("{}:{}: {}", file, line, message)));
//
// A control character moves the cursor, changes colours or retitles the window (ESC [ 2 J
// clears the screen), so each is written as an escape the reader sees ("\x1b", "\n"); so is a
// byte that is not part of UTF-8, and a C1 control (U+0080..U+009F). Everything else is kept,
// other scripts too. One function for every program that prints input.
#pragma once

#include <string>
#include <string_view>

namespace l2 {

namespace printable_detail {

// The length of the UTF-8 sequence that starts text[i] and is not a C1 control, or 0.
inline std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  unsigned min = 0;
  if (lead >= 0xc2 && lead <= 0xdf) {
    length = 2;
    min = 0xa0;  // U+0080..U+009F (C2 80..C2 9F) are C1 controls
  } else if (lead >= 0xe0 && lead <= 0xef) {
    length = 3;
    min = 0x800;
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    length = 4;
    min = 0x10000;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  unsigned code = lead & (0x7fu >> length);
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3f);
  }
  if (code < min || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return 0;
  return length;
}

}  // namespace printable_detail

inline std::string printable(std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
      ++i;
    } else if (const std::size_t n = c >= 0x80 ? printable_detail::utf8_length(text, i) : 0) {
      out.append(text.substr(i, n));
      i += n;
    } else {
      if (c == '\n') {
        out += "\\n";
      } else if (c == '\t') {
        out += "\\t";
      } else if (c == '\r') {
        out += "\\r";
      } else {
        out += "\\x";
        out += kHex[c >> 4];
        out += kHex[c & 15];
      }
      ++i;
    }
  }
  return out;
}

}  // namespace l2
