#include "tilelayout/colour_lut.hpp"

#include <fmt/format.h>

#include <array>
#include <optional>
#include <string>

#include "command_line/printable.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

constexpr int kEntries = 256;
// A quoted entry is cut here, so that a line of garbage stays a short message.
constexpr std::size_t kQuoted = 40;

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

// "12 300 4" -> {12, 300, 4}: exactly three decimal integers 0..255 separated by blanks.
std::optional<std::array<int, 3>> entry(std::string_view s) {
  std::array<int, 3> values{};
  std::size_t i = 0;
  for (int k = 0; k < 3; ++k) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    const std::size_t start = i;
    int v = 0;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9' && i - start < 4) v = v * 10 + (s[i++] - '0');
    if (i == start || v > 255) return std::nullopt;
    if (i < s.size() && s[i] != ' ' && s[i] != '\t') return std::nullopt;  // "12x", "1234"
    values[static_cast<std::size_t>(k)] = v;
  }
  if (!trim(s.substr(i)).empty()) return std::nullopt;  // a fourth value
  return values;
}

std::string quoted(std::string_view s) {
  const bool cut = s.size() > kQuoted;
  return fmt::format("\"{}{}\"", printable(s.substr(0, kQuoted)), cut ? "..." : "");
}

}  // namespace

ColourTable parse_colour_lut(std::string_view text, std::string_view name_as_given) {
  const std::string name = printable(name_as_given);
  if (text.size() > kMaxColourLutBytes) {
    throw LayoutError(fmt::format("{}: more than {} KiB: not a colour table ({} lines of R G B)",
                                  name, kMaxColourLutBytes / 1024, kEntries));
  }
  ColourTable table;
  int entries = 0, line = 0;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    std::string_view content = text.substr(at, end - at);
    at = end + 1;
    ++line;
    content = trim(content.substr(0, content.find('#')));
    if (content.empty()) continue;
    if (entries == kEntries) {
      throw LayoutError(
          fmt::format("{}:{}: more than {} entries: a table has one for each input byte 0..255",
                      name, line, kEntries));
    }
    const auto values = entry(content);
    if (!values) {
      throw LayoutError(
          fmt::format("{}:{}: expected 3 integers 0..255, got {}", name, line, quoted(content)));
    }
    for (std::size_t c = 0; c < 3; ++c)
      table.channel[c][static_cast<std::size_t>(entries)] = static_cast<std::uint8_t>((*values)[c]);
    ++entries;
  }
  if (entries != kEntries) {
    throw LayoutError(
        fmt::format("{}: {} entries, a table needs exactly {}: one for each input byte 0..255",
                    name, entries, kEntries));
  }
  return table;
}

}  // namespace l2
