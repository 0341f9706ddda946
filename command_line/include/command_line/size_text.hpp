// A size as written on a command line, "1280x1024", and lists of them, "1280x1024,640x480":
// shared so that every program reads them the same way, and none through sscanf's %d, which
// wraps 4294967360 to 64.
//
// Example:
//
//   for (const std::string& item : l2::list_items("1280x1024,640x480")) {
//     const std::optional<l2::SizeText> size = l2::parse_size_text(item);
//     if (!size) throw CLI::ValidationError("--displays", "'" + item + "' is not WIDTHxHEIGHT");
//     sizes.emplace_back(size->width, size->height);
//   }
#pragma once

#include <charconv>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace l2 {

struct SizeText {
  int width = 0, height = 0;
};

// Two decimal numbers joined by 'x' (or 'X'), nothing else: no sign, space or suffix, each
// fitting an int. nullopt otherwise; the caller names the option and the range it allows.
inline std::optional<SizeText> parse_size_text(std::string_view text) {
  const auto number = [](std::string_view digits) -> std::optional<int> {
    int value = 0;
    const char* const end = digits.data() + digits.size();
    const auto [stop, ec] = std::from_chars(digits.data(), end, value);
    if (digits.empty() || digits[0] == '-' || ec != std::errc{} || stop != end) return {};
    return value;
  };
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string_view::npos) return {};
  const auto w = number(text.substr(0, x)), h = number(text.substr(x + 1));
  if (!w || !h) return {};
  return SizeText{*w, *h};
}

// The items of a list written "a,b,c", each as written: "" is one empty item and "a," two, so
// that a stray comma reaches the caller as an item it refuses, naming its place.
inline std::vector<std::string> list_items(std::string_view text, char separator = ',') {
  std::vector<std::string> items;
  for (;;) {
    const std::size_t at = text.find(separator);
    items.emplace_back(text.substr(0, at));
    if (at == std::string_view::npos) return items;
    text.remove_prefix(at + 1);
  }
}

}  // namespace l2
