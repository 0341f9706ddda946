#include "nesting_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace l2::detail {

namespace {

// Where `end` next occurs at or after `at` (past it), or the text's end.
std::size_t after(std::string_view text, std::size_t at, std::string_view end) {
  const std::size_t found = text.find(end, at);
  return found == std::string_view::npos ? text.size() : found + end.size();
}

// The end of a tag that starts at `at` ('<' already passed): its '>', quoted values skipped.
std::size_t tag_end(std::string_view text, std::size_t at) {
  char quote = 0;
  for (; at < text.size(); ++at) {
    const char c = text[at];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '>') {
      return at;
    }
  }
  return text.size();
}

// A declaration (<!DOCTYPE ...>, <!ENTITY ...>): its '>', an internal subset's [...] included.
std::size_t declaration_end(std::string_view text, std::size_t at) {
  int brackets = 0;
  for (; at < text.size(); ++at) {
    if (text[at] == '[') ++brackets;
    if (text[at] == ']') --brackets;
    if (text[at] == '>' && brackets <= 0) return at;
  }
  return text.size();
}

// Lines up to `at`, counted from `from` (where `line` was).
int line_at(std::string_view text, std::size_t from, std::size_t at, int line) {
  return line + static_cast<int>(std::count(text.begin() + static_cast<std::ptrdiff_t>(from),
                                            text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

std::string_view without_bom(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  return text;
}

bool starts_with_any(std::string_view text, std::initializer_list<std::string_view> starts) {
  return std::any_of(starts.begin(), starts.end(),
                     [&](std::string_view s) { return text.substr(0, s.size()) == s; });
}

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

Nesting xml_nesting(std::string_view text, int stop_above) {
  text = without_bom(text);
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos || text[first] != '<') return {};
  Nesting deepest;
  int depth = 0, line = 1;
  std::size_t counted = 0;  // `line` is the line of this offset
  for (std::size_t at = text.find('<', first); at < text.size(); at = text.find('<', at)) {
    const std::string_view rest = text.substr(at + 1);
    if (rest.substr(0, 3) == "!--") {
      at = after(text, at + 4, "-->");
    } else if (rest.substr(0, 8) == "![CDATA[") {
      at = after(text, at + 9, "]]>");
    } else if (rest.substr(0, 1) == "!") {
      at = declaration_end(text, at + 2);
    } else if (rest.substr(0, 1) == "?") {
      at = after(text, at + 2, "?>");
    } else if (rest.substr(0, 1) == "/") {
      depth = std::max(depth - 1, 0);
      at = tag_end(text, at + 2);
    } else {
      const std::size_t end = tag_end(text, at + 1);
      const bool empty = end < text.size() && text[end - 1] == '/';
      if (!empty && ++depth > deepest.depth) {
        line = line_at(text, counted, at, line);
        counted = at;
        deepest = {depth, line};
        if (depth > stop_above) return deepest;
      }
      at = end;
    }
    if (at == std::string_view::npos || at >= text.size()) break;
  }
  return deepest;
}

Nesting brace_nesting(std::string_view text, int stop_above) {
  Nesting deepest;
  int depth = 0, line = 1;
  bool quoted = false;
  for (const char c : text) {
    if (c == '\n') ++line;
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    if (c == '{' && ++depth > deepest.depth) {
      deepest = {depth, line};
      if (depth > stop_above) return deepest;
    }
    if (c == '}') depth = std::max(depth - 1, 0);
  }
  return deepest;
}

void check_nesting(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return;
  const std::string text = read_all(path);
  const std::string_view start = without_bom(text);
  const auto refuse = [&](const char* what, Nesting n) {
    if (n.depth <= kMaxModelNesting) return;
    throw std::runtime_error(fmt::format("{}: {} nested deeper than {} levels (at line {})",
                                         path.string(), what, kMaxModelNesting, n.line));
  };
  refuse("XML", xml_nesting(text));
  // The text formats that nest in braces, by how they begin (binary .x and FBX do not nest so).
  if (starts_with_any(start,
                      {"xof 0302txt", "xof 0303txt", "; FBX", "*3DSMAX_ASCIIEXPORT", "MD5Version"}))
    refuse("braces", brace_nesting(text));
}

}  // namespace l2::detail
