// The manifest of the golden images (tests/golden_images/manifest.toml): for each entry, which
// wall, scene and frame its display images show, which paths produced them, what tolerance
// applies and, for rendered scenes, which OpenGL implementation rendered them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace l2 {

// The scene of routing-only entries: tilelayout's test pattern, no rendering.
inline constexpr std::string_view kTestPatternScene = "test-pattern";

enum class GoldenKind {
  RoutingOnly,  // test pattern: a change means the routing changed, so it must never change
  Rendered,     // a pipeserver scene rendered with OSMesa: depends on the Mesa version
};

// How far two sets of display images may differ, as fractions of all their pixels together.
struct Tolerance {
  bool exact = true;
  double differing_percent = 0;   // pixels that differ at all
  double beyond_one_percent = 0;  // pixels where some channel differs by more than one level

  // The documented reassembly tolerance (pipeserver/README.md, "Reassembly tolerance").
  static Tolerance reassembly() { return {false, 0.01, 0.003}; }
  bool allows(std::uint64_t differing, std::uint64_t beyond_one, std::uint64_t pixels) const;
  std::string describe() const;  // "exact" or "<= 0.01% of pixels differ, <= 0.003% by > 1"
};

struct GoldenEntry {
  std::string name;  // also the folder of its images: <name>/display-<id>.png
  GoldenKind kind = GoldenKind::RoutingOnly;
  std::string wall;                     // wall file, relative to the repository root
  std::string scene;                    // kTestPatternScene or a pipeserver scene
  std::string session;                  // scene "session": its file, relative to the repository
  int frame = 0;                        // application frame (its parity goes into the headers)
  bool vizserver = true;                // also run the viz path (DVI always runs)
  Tolerance tolerance;                  // reassembled against the reference; golden on another GL
  std::string mesa;                     // rendered: the Mesa release that made the images ...
  std::string gl_version, gl_renderer;  // ... and how GL named itself then
  int line = 0;                         // of its [[entry]] in the manifest, for messages
};

struct GoldenManifest {
  std::vector<GoldenEntry> entries;
  const GoldenEntry* find(std::string_view name) const;
};

// A manifest that cannot be used, or a golden folder that does not match it. One line naming
// file, line and field where known: "manifest.toml:12: entry.frame: must be 0..100000, got -1".
class GoldenError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

GoldenManifest parse_manifest(std::string_view toml_text, const std::string& file_for_messages);
GoldenManifest load_manifest(const std::filesystem::path& file);

// The manifest as `l2wall golden update` writes it: every field, one entry after another.
std::string format_manifest(const GoldenManifest& manifest);

}  // namespace l2
