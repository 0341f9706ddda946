// Text that came from outside (a peer on the network, a file) made safe to print on a terminal
// or in a log: one line, and nothing the terminal would act on. Control characters and escape
// sequences written raw could clear the screen, move the cursor, set the window title, or
// fake a line of output; written escaped they are seen for what they are.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace l2 {

namespace escape_detail {

inline void put_hex(std::string& out, unsigned char byte) {
  constexpr char kDigits[] = "0123456789abcdef";
  out += "\\x";
  out += kDigits[byte >> 4];
  out += kDigits[byte & 0xF];
}

// The length of the well-formed UTF-8 sequence at text[i] (2..4), or 0: a lone, truncated,
// overlong or surrogate sequence, which is escaped byte by byte.
inline std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(text[i + k]); };
  const unsigned char lead = b(0);
  const std::size_t n = lead >= 0xF0 && lead <= 0xF4 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((b(k) & 0xC0) != 0x80) return 0;
  }
  if (n == 3 && ((lead == 0xE0 && b(1) < 0xA0) || (lead == 0xED && b(1) >= 0xA0))) return 0;
  if (n == 4 && ((lead == 0xF0 && b(1) < 0x90) || (lead == 0xF4 && b(1) >= 0x90))) return 0;
  return n;
}

}  // namespace escape_detail

// Printable ASCII and well-formed UTF-8 pass through. Everything else is written as C escapes:
// \n \r \t, and \xHH for every other control character (C0, DEL), the C1 controls
// U+0080..U+009F (an 8-bit CSI is one of them) and every byte that is not part of well-formed
// UTF-8. A backslash stays as it is, so that text escaped twice (a peer's words inside a
// failure line that is passed on) reads the same as text escaped once.
inline std::string escape_for_terminal(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7F) {
      out += static_cast<char>(c);
      ++i;
      continue;
    }
    if (c == '\n' || c == '\r' || c == '\t') {
      out += c == '\n' ? "\\n" : c == '\r' ? "\\r" : "\\t";
      ++i;
      continue;
    }
    const std::size_t n = c >= 0x80 ? escape_detail::utf8_length(text, i) : 0;
    const bool c1_control = n == 2 && c == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0;
    if (n == 0 || c1_control) {
      const std::size_t bytes = c1_control ? 2 : 1;
      for (std::size_t k = 0; k < bytes; ++k) {
        escape_detail::put_hex(out, static_cast<unsigned char>(text[i + k]));
      }
      i += bytes;
      continue;
    }
    out.append(text.substr(i, n));
    i += n;
  }
  return out;
}

}  // namespace l2
