#include "golden_manifest.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "pipeserver/scene.hpp"
#include "tilelayout/toml_text.hpp"

namespace l2 {

bool Tolerance::allows(std::uint64_t differing, std::uint64_t beyond_one,
                       std::uint64_t pixels) const {
  if (exact) return differing == 0;
  // Rounded down, as the reassembly tests do: on a few thousand pixels nothing may differ.
  const auto limit = [pixels](double percent) {
    return static_cast<std::uint64_t>(std::floor(static_cast<double>(pixels) * percent / 100.0));
  };
  return differing <= limit(differing_percent) && beyond_one <= limit(beyond_one_percent);
}

std::string Tolerance::describe() const {
  if (exact) return "exact";
  return fmt::format("<= {}% of pixels differ, <= {}% by more than one level", differing_percent,
                     beyond_one_percent);
}

const GoldenEntry* GoldenManifest::find(std::string_view name) const {
  for (const GoldenEntry& e : entries) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

namespace {

int line_of(const toml::node& node) {
  return static_cast<int>(node.source().begin.line);
}

// Reads the fields of one [[entry]] table; every error names file, line and field.
class EntryReader {
 public:
  EntryReader(const toml::table& table, const std::string& file) : table_(table), file_(file) {}

  [[noreturn]] void fail(int line, std::string_view key, std::string_view message) const {
    throw GoldenError(fmt::format("{}:{}: entry.{}: {}", file_, line, key, message));
  }
  [[noreturn]] void fail(std::string_view key, std::string_view message) const {
    const toml::node* n = table_.get(key);
    fail(n ? line_of(*n) : line_of(table_), key, message);
  }

  void reject_unknown_keys() const {
    static const std::vector<std::string_view> known{
        "name",  "kind",      "wall", "scene",      "session",    "frame",
        "paths", "tolerance", "mesa", "gl_version", "gl_renderer"};
    for (const auto& [key, node] : table_) {
      if (std::find(known.begin(), known.end(), key.str()) == known.end()) {
        fail(static_cast<int>(key.source().begin.line), key.str(), "unknown key");
      }
    }
  }

  std::string string(std::string_view key, bool required) const {
    const toml::node* n = table_.get(key);
    if (!n) {
      if (required) fail(key, "missing (required)");
      return {};
    }
    if (!n->is_string()) fail(key, "must be a string");
    return n->as_string()->get();
  }

  int integer(std::string_view key, long long min, long long max) const {
    const toml::node* n = table_.get(key);
    if (!n) fail(key, "missing (required)");
    if (!n->is_integer()) fail(key, "must be an integer");
    const long long v = n->as_integer()->get();
    if (v < min || v > max) fail(key, fmt::format("must be {}..{}, got {}", min, max, v));
    return static_cast<int>(v);
  }

  double percent(const toml::table& t, std::string_view key) const {
    const toml::node* n = t.get(key);
    if (!n) fail("tolerance", fmt::format("{} missing", key));
    const auto v = n->value<double>();  // an integer reads as a number too
    // NaN would pass the range check and make Tolerance::allows convert floor(NaN) to an integer.
    if (!v || !std::isfinite(*v) || *v < 0 || *v > 100) {
      fail("tolerance", fmt::format("{} must be 0..100", key));
    }
    return *v;
  }

  Tolerance tolerance() const {
    const toml::node* n = table_.get("tolerance");
    if (!n) fail("tolerance", "missing (required)");
    if (n->is_string() && n->as_string()->get() == "exact") return {};
    if (!n->is_table()) {
      fail("tolerance", "must be \"exact\" or { differing_percent = P, beyond_one_percent = Q }");
    }
    const toml::table& t = *n->as_table();
    for (const auto& [key, value] : t) {
      if (key != "differing_percent" && key != "beyond_one_percent") {
        fail("tolerance", fmt::format("unknown key {}", key.str()));
      }
    }
    return {false, percent(t, "differing_percent"), percent(t, "beyond_one_percent")};
  }

  // ["dvi"] or ["dvi", "vizserver"]: returns whether the vizserver path runs.
  bool paths() const {
    const toml::node* n = table_.get("paths");
    if (!n) fail("paths", "missing (required)");
    if (!n->is_array()) fail("paths", "must be an array of strings");
    bool dvi = false, vizserver = false;
    for (const toml::node& p : *n->as_array()) {
      const auto s = p.value<std::string>();
      if (s == "dvi") {
        dvi = true;
      } else if (s == "vizserver") {
        vizserver = true;
      } else {
        fail(line_of(p), "paths", "each path must be \"dvi\" or \"vizserver\"");
      }
    }
    // The golden images are the emulator's displays: the DVI path always runs.
    if (!dvi) fail("paths", "must include \"dvi\"");
    return vizserver;
  }

  int line() const { return line_of(table_); }

 private:
  const toml::table& table_;
  const std::string& file_;
};

bool valid_name(const std::string& name) {
  return !name.empty() && name.front() != '.' && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
  });
}

// A rendered entry shows a built-in scene, or a session (windows of them) from its file.
void check_rendered_scene(const EntryReader& r, const GoldenEntry& e) {
  if (e.scene == "session") {
    if (e.session.empty()) r.fail("session", "missing: scene \"session\" names its session file");
    return;
  }
  if (!e.session.empty()) r.fail("session", "only with scene \"session\"");
  std::vector<std::string> scenes = built_in_scene_names();
  if (std::find(scenes.begin(), scenes.end(), e.scene) == scenes.end()) {
    scenes.push_back("session");
    r.fail("scene", fmt::format("must be one of {}, got \"{}\"", fmt::join(scenes, ", "), e.scene));
  }
}

GoldenEntry read_entry(const toml::table& table, const std::string& file) {
  const EntryReader r(table, file);
  r.reject_unknown_keys();
  GoldenEntry e;
  e.line = r.line();
  e.name = r.string("name", true);
  if (!valid_name(e.name)) {
    r.fail("name", "must be letters, digits, '-', '_' or '.' (it names a folder)");
  }
  const std::string kind = r.string("kind", true);
  if (kind != "routing-only" && kind != "rendered") {
    r.fail("kind", fmt::format("must be \"routing-only\" or \"rendered\", got \"{}\"", kind));
  }
  e.kind = kind == "rendered" ? GoldenKind::Rendered : GoldenKind::RoutingOnly;
  e.wall = r.string("wall", true);
  e.scene = r.string("scene", true);
  e.session = r.string("session", false);
  e.frame = r.integer("frame", 0, 100000);
  e.vizserver = r.paths();
  e.tolerance = r.tolerance();
  e.mesa = r.string("mesa", false);
  e.gl_version = r.string("gl_version", false);
  e.gl_renderer = r.string("gl_renderer", false);
  if (e.kind == GoldenKind::RoutingOnly) {
    if (e.scene != kTestPatternScene) r.fail("scene", "routing-only entries use \"test-pattern\"");
    if (!e.session.empty()) r.fail("session", "only with scene \"session\"");
    if (!e.tolerance.exact) r.fail("tolerance", "routing-only entries are \"exact\"");
    if (!e.mesa.empty() || !e.gl_version.empty() || !e.gl_renderer.empty()) {
      r.fail("mesa", "routing-only entries render nothing: no Mesa version");
    }
  } else {
    check_rendered_scene(r, e);
  }
  return e;
}

}  // namespace

GoldenManifest parse_manifest(std::string_view toml_text, const std::string& file) {
  toml::table doc;
  try {
    doc = toml::parse(toml_text, file);
  } catch (const toml::parse_error& e) {
    throw GoldenError(
        fmt::format("{}:{}: malformed TOML: {}", file, e.source().begin.line, e.description()));
  }
  GoldenManifest manifest;
  for (const auto& [key, node] : doc) {
    if (key != "entry") {
      throw GoldenError(
          fmt::format("{}:{}: {}: unknown key", file, key.source().begin.line, key.str()));
    }
  }
  const toml::array* entries = doc["entry"].as_array();
  if (!entries || entries->empty()) throw GoldenError(file + ": no [[entry]] tables");
  for (const toml::node& node : *entries) {
    if (!node.is_table()) throw GoldenError(file + ": entry must be [[entry]] tables");
    GoldenEntry e = read_entry(*node.as_table(), file);
    if (manifest.find(e.name)) {
      throw GoldenError(fmt::format("{}:{}: entry.name: \"{}\" given twice", file, e.line, e.name));
    }
    manifest.entries.push_back(std::move(e));
  }
  return manifest;
}

GoldenManifest load_manifest(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw GoldenError(file.string() + ": cannot read the golden manifest");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_manifest(text.str(), file.string());
}

std::string format_manifest(const GoldenManifest& manifest) {
  std::string out =
      "# Golden images of display reassembly: for each entry, the displays of one wall showing\n"
      "# one frame, in <name>/display-<id>.png. `l2wall golden check` reproduces and compares\n"
      "# them; `l2wall golden update` regenerates them and rewrites this file (entries may be\n"
      "# added or edited by hand; comments are not kept). Fields: README.md in this folder.\n";
  for (const GoldenEntry& e : manifest.entries) {
    const bool rendered = e.kind == GoldenKind::Rendered;
    out += fmt::format("\n[[entry]]\nname = {}\nkind = {}\nwall = {}\nscene = {}\nframe = {}\n",
                       toml_quoted(e.name), rendered ? "\"rendered\"" : "\"routing-only\"",
                       toml_quoted(e.wall), toml_quoted(e.scene), e.frame);
    if (!e.session.empty()) out += fmt::format("session = {}\n", toml_quoted(e.session));
    out += e.vizserver ? "paths = [\"dvi\", \"vizserver\"]\n" : "paths = [\"dvi\"]\n";
    out += e.tolerance.exact ? "tolerance = \"exact\"\n"
                             : fmt::format(
                                   "tolerance = {{ differing_percent = {}, "
                                   "beyond_one_percent = {} }}\n",
                                   e.tolerance.differing_percent, e.tolerance.beyond_one_percent);
    if (rendered) {
      out += fmt::format("mesa = {}\ngl_version = {}\ngl_renderer = {}\n", toml_quoted(e.mesa),
                         toml_quoted(e.gl_version), toml_quoted(e.gl_renderer));
    }
  }
  return out;
}

}  // namespace l2
