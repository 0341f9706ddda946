// What `l2wall golden check` and `update` share: where the golden images are, which entries
// were asked for, producing an entry's displays, and comparing sets of display images.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "display_compare.hpp"
#include "golden_manifest.hpp"
#include "golden_routing.hpp"
#include "pipeserver/gl_context.hpp"

namespace l2 {

struct GoldenPaths {
  std::filesystem::path goldens;  // manifest.toml and <entry>/display-<id>.png
  std::filesystem::path root;     // where the manifest's wall paths start (the repository)

  std::filesystem::path manifest() const { return goldens / "manifest.toml"; }
  std::filesystem::path image(const GoldenEntry& e, int display) const;
  // The command a hint tells the user to run: "l2wall golden <subcommand> --goldens G --root
  // R" with these folders, quoted for a shell where they need it, then `extra` (" --entry X").
  std::string command(const std::string& subcommand, const std::string& extra) const;
};

// `text` as one shell word: as it is when it holds only safe characters, else in single quotes.
std::string shell_word(const std::string& text);

// The executables rendered entries are made with.
struct GoldenTools {
  std::string l2wall;              // `l2wall run`: the live run on both paths
  std::string pipeserver_program;  // `pipeserver --reference`, `--gl-info`
};

// The entries named (all when `names` is empty), in manifest order. Throws GoldenError for a
// name the manifest does not have, listing the ones it has.
std::vector<const GoldenEntry*> select_entries(const GoldenManifest& manifest,
                                               const std::vector<std::string>& names);

// The entry's displays on every path it names, and the reference. Rendered entries run the
// tools as child processes, in `work`.
EntryDisplays produce_entry(const GoldenEntry& entry, const GoldenPaths& paths,
                            const GoldenTools& tools, const std::filesystem::path& work);

// Whether the golden images of a rendered entry were made by this very GL implementation.
bool same_renderer(const GoldenEntry& entry, const GlInfo& gl);
std::string describe_renderer(const std::string& mesa, const std::string& renderer);

// Two sets of display images (one per display, same order) against a tolerance over all
// their pixels together.
struct SetComparison {
  std::vector<DisplayDiff> displays;
  std::uint64_t pixels = 0, differing = 0, beyond_one = 0;
  bool passed = true;
};
SetComparison compare_sets(const std::vector<RgbImage>& expected,
                           const std::vector<RgbImage>& actual, const Tolerance& tolerance);

// "1 pixel differs (1 by more than one level), largest difference 200 at (100, 50)".
std::string describe_diff(const DisplayDiff& diff);

}  // namespace l2
