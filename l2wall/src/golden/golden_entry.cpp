#include "golden_entry.hpp"

#include <fmt/format.h>

#include "golden_rendered.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {

std::filesystem::path GoldenPaths::image(const GoldenEntry& e, int display) const {
  return goldens / e.name / fmt::format("display-{}.png", display);
}

std::string shell_word(const std::string& text) {
  const bool safe = !text.empty() && text.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyz"
                                         "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789_-./:=+,") == text.npos;
  if (safe) return text;
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string GoldenPaths::command(const std::string& subcommand, const std::string& extra) const {
  return fmt::format("l2wall golden {} --goldens {} --root {}{}", subcommand,
                     shell_word(goldens.string()), shell_word(root.string()), extra);
}

std::vector<const GoldenEntry*> select_entries(const GoldenManifest& manifest,
                                               const std::vector<std::string>& names) {
  std::vector<const GoldenEntry*> out;
  for (const GoldenEntry& e : manifest.entries) {
    if (names.empty() || std::find(names.begin(), names.end(), e.name) != names.end()) {
      out.push_back(&e);
    }
  }
  for (const std::string& n : names) {
    if (manifest.find(n)) continue;
    std::vector<std::string> known;
    for (const GoldenEntry& e : manifest.entries) known.push_back(e.name);
    throw GoldenError(
        fmt::format("--entry {}: no such entry; the manifest has {}", n, fmt::join(known, ", ")));
  }
  return out;
}

EntryDisplays produce_entry(const GoldenEntry& entry, const GoldenPaths& paths,
                            const GoldenTools& tools, const std::filesystem::path& work) {
  const auto wall_file = paths.root / entry.wall;
  const TileLayout layout = plan_layout(load_wall(wall_file));
  if (entry.kind == GoldenKind::RoutingOnly) {
    return produce_test_pattern(layout, entry.frame, entry.vizserver);
  }
  RenderedRun run{tools.l2wall, tools.pipeserver_program, work, {}};
  if (!entry.session.empty()) run.session = paths.root / entry.session;
  return produce_rendered(layout, wall_file, entry, run);
}

bool same_renderer(const GoldenEntry& entry, const GlInfo& gl) {
  return entry.gl_version == gl.version && entry.gl_renderer == gl.renderer;
}

std::string describe_renderer(const std::string& mesa, const std::string& renderer) {
  if (mesa.empty() && renderer.empty()) return "an unrecorded GL";
  return fmt::format("Mesa {} ({})", mesa.empty() ? "?" : mesa, renderer);
}

SetComparison compare_sets(const std::vector<RgbImage>& expected,
                           const std::vector<RgbImage>& actual, const Tolerance& tolerance) {
  SetComparison c;
  for (std::size_t i = 0; i < actual.size(); ++i) {
    const RgbImage& e = expected.at(i);
    c.displays.push_back(compare_displays(e, actual[i]));
    c.pixels += static_cast<std::uint64_t>(actual[i].width()) * actual[i].height();
    c.differing += c.displays.back().differing_pixels;
    c.beyond_one += c.displays.back().beyond_one;
    // A different size can never be within a tolerance.
    if (c.displays.back().size_differs) c.passed = false;
  }
  c.passed = c.passed && tolerance.allows(c.differing, c.beyond_one, c.pixels);
  return c;
}

std::string describe_diff(const DisplayDiff& d) {
  if (d.size_differs) return "the sizes differ";
  return fmt::format(
      "{} pixel{} differ{} ({} by more than one level), largest difference {} at "
      "({}, {})",
      d.differing_pixels, d.differing_pixels == 1 ? "" : "s", d.differing_pixels == 1 ? "s" : "",
      d.beyond_one, d.largest, d.largest_x, d.largest_y);
}

}  // namespace l2
