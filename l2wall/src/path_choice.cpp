#include "l2wall/path_choice.hpp"

#include <array>
#include <utility>

namespace l2 {
namespace {

constexpr std::array<std::pair<std::string_view, PathChoice>, 3> kNames{{
    {"dvi", PathChoice::Dvi},
    {"vizserver", PathChoice::Vizserver},
    {"both", PathChoice::Both},
}};

}  // namespace

std::optional<PathChoice> parse_path_choice(std::string_view name) {
  for (const auto& [text, path] : kNames)
    if (text == name) return path;
  return std::nullopt;
}

std::string_view path_choice_name(PathChoice path) {
  for (const auto& [text, p] : kNames)
    if (p == path) return text;
  return "?";
}

}  // namespace l2
