// The golden manifest: what it accepts, the one-line errors for what it does not, and the
// repository's own manifest.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "golden/golden_manifest.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

const char* kTwoEntries = R"toml(
[[entry]]
name = "kd-2x2-test-pattern"
kind = "routing-only"
wall = "walls/kd-2x2.toml"
scene = "test-pattern"
frame = 1
paths = ["dvi", "vizserver"]
tolerance = "exact"

[[entry]]
name = "bunny"
kind = "rendered"
wall = "walls/kd-2x2.toml"
scene = "mesh"
frame = 3
paths = ["dvi"]
tolerance = { differing_percent = 0.01, beyond_one_percent = 0.003 }
mesa = "22.3.6"
gl_version = "4.5 (Compatibility Profile) Mesa 22.3.6"
gl_renderer = "llvmpipe (LLVM 15.0.6, 256 bits)"
)toml";

TEST(GoldenManifest, ReadsEveryField) {
  const GoldenManifest m = parse_manifest(kTwoEntries, "m.toml");
  ASSERT_EQ(m.entries.size(), 2u);
  const GoldenEntry& t = m.entries[0];
  EXPECT_EQ(t.name, "kd-2x2-test-pattern");
  EXPECT_EQ(t.kind, GoldenKind::RoutingOnly);
  EXPECT_EQ(t.wall, "walls/kd-2x2.toml");
  EXPECT_EQ(t.frame, 1);
  EXPECT_TRUE(t.vizserver);
  EXPECT_TRUE(t.tolerance.exact);
  EXPECT_EQ(t.line, 2);
  const GoldenEntry& b = m.entries[1];
  EXPECT_EQ(b.kind, GoldenKind::Rendered);
  EXPECT_EQ(b.scene, "mesh");
  EXPECT_FALSE(b.vizserver);
  EXPECT_FALSE(b.tolerance.exact);
  EXPECT_DOUBLE_EQ(b.tolerance.differing_percent, 0.01);
  EXPECT_DOUBLE_EQ(b.tolerance.beyond_one_percent, 0.003);
  EXPECT_EQ(b.mesa, "22.3.6");
  EXPECT_EQ(b.gl_renderer, "llvmpipe (LLVM 15.0.6, 256 bits)");
  EXPECT_EQ(m.find("bunny"), &m.entries[1]);
  EXPECT_EQ(m.find("rabbit"), nullptr);
}

TEST(GoldenManifest, WritesWhatItReads) {
  const GoldenManifest m = parse_manifest(kTwoEntries, "m.toml");
  const std::string text = format_manifest(m);
  EXPECT_EQ(format_manifest(parse_manifest(text, "again.toml")), text);
  const GoldenManifest again = parse_manifest(text, "again.toml");
  EXPECT_EQ(again.entries[1].gl_version, m.entries[1].gl_version);
  EXPECT_EQ(again.entries[1].tolerance.beyond_one_percent, 0.003);
}

// A session entry: its file is read, written back, and only there.
TEST(GoldenManifest, ASessionEntryKeepsItsFile) {
  const GoldenManifest m =
      parse_manifest(std::string(kTwoEntries)
                         .replace(std::string(kTwoEntries).find("scene = \"mesh\""), 14,
                                  "scene = \"session\"\nsession = \"sessions/w.toml\""),
                     "m.toml");
  EXPECT_EQ(m.entries[1].scene, "session");
  EXPECT_EQ(m.entries[1].session, "sessions/w.toml");
  EXPECT_TRUE(m.entries[0].session.empty());
  const std::string text = format_manifest(m);
  EXPECT_NE(text.find("scene = \"session\"\nframe = 3\nsession = \"sessions/w.toml\"\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(format_manifest(parse_manifest(text, "again.toml")), text);
}

// Strings are written as TOML basic strings with every control character escaped: a renderer
// name with a newline or a control byte in it used to make a manifest that could not be read.
TEST(GoldenManifest, WritesControlCharactersItCanReadBack) {
  GoldenManifest m = parse_manifest(kTwoEntries, "m.toml");
  const std::string odd[] = {"llvmpipe\n(LLVM 15.0.6)", std::string("a\0b\x01\x1f\x7f", 7),
                             "tab\there\r\b\f", "quote \" backslash \\ \\u0041 done",
                             "UTF-8 \xc3\xa9 kept"};
  for (const std::string& s : odd) {
    m.entries[1].gl_renderer = s;
    m.entries[1].mesa = s + "!";
    m.entries[0].wall = "walls/" + s + ".toml";
    const std::string text = format_manifest(m);
    GoldenManifest again;
    ASSERT_NO_THROW(again = parse_manifest(text, "again.toml")) << text;
    EXPECT_EQ(again.entries[1].gl_renderer, s);
    EXPECT_EQ(again.entries[1].mesa, s + "!");
    EXPECT_EQ(again.entries[0].wall, "walls/" + s + ".toml");
    EXPECT_EQ(format_manifest(again), text);
  }
  m.entries[1].gl_renderer = std::string("a\nb\x01\tc", 6);
  EXPECT_NE(format_manifest(m).find("gl_renderer = \"a\\nb\\u0001\\tc\"\n"), std::string::npos)
      << format_manifest(m);
}

std::string error_of(const std::string& text) {
  try {
    parse_manifest(text, "m.toml");
  } catch (const GoldenError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string with(const std::string& from, const std::string& to) {
  std::string text = kTwoEntries;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(GoldenManifest, ErrorsNameFileLineAndField) {
  EXPECT_EQ(error_of(with("frame = 1", "frame = -1")),
            "m.toml:7: entry.frame: must be 0..100000, got -1");
  EXPECT_EQ(error_of(with("frame = 1", "frames = 1")), "m.toml:7: entry.frames: unknown key");
  EXPECT_EQ(error_of(with("kind = \"routing-only\"", "kind = \"routed\"")),
            "m.toml:4: entry.kind: must be \"routing-only\" or \"rendered\", got \"routed\"");
  EXPECT_EQ(error_of(with("scene = \"test-pattern\"", "scene = \"mesh\"")),
            "m.toml:6: entry.scene: routing-only entries use \"test-pattern\"");
  EXPECT_EQ(error_of(with("scene = \"mesh\"", "scene = \"teapot\"")),
            "m.toml:15: entry.scene: must be one of mesh, strips, hotspot, isosurface, patches, "
            "swap, session, got \"teapot\"");
  EXPECT_EQ(error_of(with("scene = \"mesh\"", "scene = \"session\"")),
            "m.toml:11: entry.session: missing: scene \"session\" names its session file");
  EXPECT_EQ(error_of(with("scene = \"mesh\"", "scene = \"mesh\"\nsession = \"s.toml\"")),
            "m.toml:16: entry.session: only with scene \"session\"");
  EXPECT_EQ(
      error_of(with("scene = \"test-pattern\"", "scene = \"test-pattern\"\nsession = \"s.toml\"")),
      "m.toml:7: entry.session: only with scene \"session\"");
  EXPECT_EQ(error_of(with("paths = [\"dvi\"]", "paths = [\"vizserver\"]")),
            "m.toml:17: entry.paths: must include \"dvi\"");
  EXPECT_EQ(error_of(with("paths = [\"dvi\"]", "paths = [\"dvi\", \"hdmi\"]")),
            "m.toml:17: entry.paths: each path must be \"dvi\" or \"vizserver\"");
  EXPECT_EQ(error_of(with("tolerance = \"exact\"", "tolerance = \"loose\"")),
            "m.toml:9: entry.tolerance: must be \"exact\" or { differing_percent = P, "
            "beyond_one_percent = Q }");
  EXPECT_EQ(error_of(with("beyond_one_percent = 0.003", "beyond_one_percent = 300")),
            "m.toml:18: entry.tolerance: beyond_one_percent must be 0..100");
  // NaN passed the range check, and Tolerance::allows then converted floor(NaN) to an integer.
  EXPECT_EQ(error_of(with("beyond_one_percent = 0.003", "beyond_one_percent = nan")),
            "m.toml:18: entry.tolerance: beyond_one_percent must be 0..100");
  EXPECT_EQ(error_of(with("differing_percent = 0.01", "differing_percent = -nan")),
            "m.toml:18: entry.tolerance: differing_percent must be 0..100");
  EXPECT_EQ(error_of(with("differing_percent = 0.01", "differing_percent = inf")),
            "m.toml:18: entry.tolerance: differing_percent must be 0..100");
  EXPECT_EQ(error_of(with("name = \"bunny\"", "name = \"kd-2x2-test-pattern\"")),
            "m.toml:11: entry.name: \"kd-2x2-test-pattern\" given twice");
  EXPECT_EQ(error_of(with("name = \"bunny\"", "name = \"../bunny\"")),
            "m.toml:12: entry.name: must be letters, digits, '-', '_' or '.' (it names a folder)");
  EXPECT_EQ(error_of(with("wall = \"walls/kd-2x2.toml\"\nscene = \"test", "scene = \"test")),
            "m.toml:2: entry.wall: missing (required)");
  EXPECT_EQ(error_of("[[entry]]\nname = \"x\n").rfind("m.toml:2: malformed TOML: ", 0), 0u);
  EXPECT_EQ(error_of("title = 1\n"), "m.toml:1: title: unknown key");
}

// The repository's manifest: a test-pattern entry for every example wall, rendered entries
// that record the Mesa that made them.
TEST(GoldenManifest, TheRepositoryManifestCoversEveryExampleWall) {
  const std::filesystem::path root = L2_SOURCE_DIR;
  const GoldenManifest m = load_manifest(root / "tests/golden_images/manifest.toml");
  std::set<std::string> walls_with_pattern;
  int rendered = 0;
  for (const GoldenEntry& e : m.entries) {
    EXPECT_TRUE(std::filesystem::exists(root / e.wall)) << e.wall;
    if (!e.session.empty()) {
      EXPECT_TRUE(std::filesystem::exists(root / e.session)) << e.session;
    }
    if (e.kind == GoldenKind::RoutingOnly) walls_with_pattern.insert(e.wall);
    if (e.kind == GoldenKind::Rendered) {
      ++rendered;
      EXPECT_FALSE(e.mesa.empty()) << e.name;
      EXPECT_FALSE(e.gl_renderer.empty()) << e.name;
    }
  }
  // Wall files only: walls/ also holds what they name (calibration/, colour tables). A wall of
  // several meshes is hundreds of full-size panels: its reduced copy in examples/walls/ has
  // the entry instead.
  for (const auto& f : std::filesystem::directory_iterator(root / "walls")) {
    if (f.path().extension() != ".toml" || load_wall(f.path()).mesh_count > 1) continue;
    EXPECT_EQ(walls_with_pattern.count("walls/" + f.path().filename().string()), 1u) << f.path();
  }
  EXPECT_GE(rendered, 2);
}

}  // namespace
}  // namespace l2
