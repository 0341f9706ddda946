// --path: which display paths a run drives, parsed once from the command line. The DVI path is
// the emulated Lightning-2 fed by the links; the viz path the compositing server fed with tiles
// over the network. Everything else asks these questions, never the option's text.
//
// Example:
//   const std::optional<PathChoice> p = parse_path_choice("both");
//   if (p && runs_viz(*p)) start_compositing_server();
//   fmt::print("paths: {}\n", path_choice_name(*p));  // "paths: both"
#pragma once

#include <optional>
#include <string_view>

namespace l2 {

enum class PathChoice { Dvi, Vizserver, Both };

// "dvi", "vizserver" or "both"; nullopt for anything else (case matters, as for --balance).
std::optional<PathChoice> parse_path_choice(std::string_view name);
std::string_view path_choice_name(PathChoice path);

// Whether the emulator runs (its refreshes then pace the run) and whether the compositing
// server does.
constexpr bool runs_dvi(PathChoice path) {
  return path != PathChoice::Vizserver;
}
constexpr bool runs_viz(PathChoice path) {
  return path != PathChoice::Dvi;
}

}  // namespace l2
