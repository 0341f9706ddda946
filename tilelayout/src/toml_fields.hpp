// Typed, range-checked reads from one TOML table, with errors that name the file, the line and
// the dotted field ("walls/x.toml:12: tiling.tile_width: must be 1..4095, got 0"). Private to
// the loaders of wall and session files.
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace l2 {

// Where a wall file's text came from, for messages.
struct TomlSource {
  std::string file;
  [[noreturn]] void fail(int line, std::string_view field, std::string_view message) const;
  [[noreturn]] void fail(const toml::node& at, std::string_view field,
                         std::string_view message) const;
};

// A file's text, read with a limit: a wall or session file is a few kilobytes, and /dev/zero or
// a wrong file (a frame dump, a log) would otherwise be read to the end of memory before TOML
// refuses it. `kind` names what it should be ("a wall file"). Throws LayoutError. A file read
// for another kind of data (a warp, tilelayout/warp_file.hpp) passes its own limit.
inline constexpr std::size_t kMaxTomlBytes = 16u << 20;
std::string read_toml_file(const std::filesystem::path& path, std::string_view kind,
                           std::size_t max_bytes = kMaxTomlBytes);
// The text parsed, its shape checked first (toml_shape.hpp). Throws LayoutError
// ("x.toml:3: malformed TOML: ...").
toml::table parse_toml(std::string_view text, const TomlSource& source);

class TomlFields {
 public:
  // Throws on the first key (by line) that is not in `allowed`: a typo must not be ignored.
  TomlFields(const toml::table& table, std::string prefix, const TomlSource& source,
             std::initializer_list<std::string_view> allowed);

  bool has(std::string_view key) const { return table_.contains(key); }
  const toml::node* node(std::string_view key) const { return table_.get(key); }
  int line() const;  // the table's own line (for fields that are missing)
  int line_of(std::string_view key) const;
  std::string field(std::string_view key) const;  // "prefix.key"

  std::optional<int> integer(std::string_view key, long long min, long long max) const;
  int integer(std::string_view key, long long min, long long max, int fallback) const;
  int required_integer(std::string_view key, long long min, long long max) const;
  // A number (integer or not) from `min` up to below `below`; `fallback` when missing.
  double fraction(std::string_view key, double min, double below, double fallback) const;
  std::optional<std::string> string(std::string_view key) const;
  bool boolean(std::string_view key, bool fallback) const;
  // One of `choices`; returns its index.
  int choice(std::string_view key, const std::vector<std::string_view>& choices,
             int fallback) const;
  const toml::array* array(std::string_view key) const;
  const toml::table* table(std::string_view key) const;

  [[noreturn]] void fail(std::string_view key, std::string_view message) const;
  const TomlSource& source() const { return source_; }

 private:
  const toml::table& table_;
  std::string prefix_;
  const TomlSource& source_;
};

// "integer", "string", ... for "must be an integer, got string".
const char* type_name(const toml::node& node);
int line_of(const toml::node& node);
// An integer element of an array, range-checked; `field` names it in errors.
int array_integer(const toml::node& node, const std::string& field, const TomlSource& source,
                  long long min, long long max);

}  // namespace l2
