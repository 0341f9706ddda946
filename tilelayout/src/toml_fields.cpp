#include "toml_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "base/nearest_word.hpp"
#include "command_line/printable.hpp"
#include "tilelayout/tile_layout.hpp"
#include "toml_shape.hpp"

namespace l2 {

// The field (a key) and the message (a value) may be the file's own text: printable.
void TomlSource::fail(int line, std::string_view field, std::string_view message) const {
  if (line > 0) {
    throw LayoutError(printable(fmt::format("{}:{}: {}: {}", file, line, field, message)));
  }
  throw LayoutError(printable(fmt::format("{}: {}: {}", file, field, message)));
}

void TomlSource::fail(const toml::node& at, std::string_view field,
                      std::string_view message) const {
  fail(line_of(at), field, message);
}

std::string read_toml_file(const std::filesystem::path& path, std::string_view kind,
                           std::size_t max_bytes) {
  // A directory opens as a stream here and reads as nothing, which would be reported as a file
  // without content. (Not "anything but a regular file": a pipe such as <(...) is fine.)
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw LayoutError(fmt::format("{}: cannot read: {}", path.string(), std::strerror(EISDIR)));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw LayoutError(fmt::format("{}: cannot read: {}", path.string(), std::strerror(errno)));
  }
  // Room for the file as its size says, one byte over the limit at most: a large limit (a
  // warp's) is not allocated for a small file. A pipe has no size and gets the whole limit.
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  const std::size_t room =
      error ? max_bytes : static_cast<std::size_t>(std::min<std::uintmax_t>(size, max_bytes));
  std::string text(room + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > max_bytes) {
    const std::string limit = max_bytes % (1u << 20) == 0 ? fmt::format("{} MiB", max_bytes >> 20)
                                                          : fmt::format("{} bytes", max_bytes);
    throw LayoutError(fmt::format("{}: more than {}: not {}", path.string(), limit, kind));
  }
  return text;
}

toml::table parse_toml(std::string_view text, const TomlSource& source) {
  check_toml_shape(text, source.file);
  try {
    return toml::parse(text, source.file);
  } catch (const toml::parse_error& e) {
    const int line = static_cast<int>(e.source().begin.line);
    // The description quotes the file: escaped, it stays one line and cannot reach a terminal.
    throw LayoutError(
        fmt::format("{}:{}: malformed TOML: {}", source.file, line, printable(e.description())));
  }
}

int line_of(const toml::node& node) {
  return static_cast<int>(node.source().begin.line);
}

const char* type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "a boolean";
    default:
      return "a date or time";
  }
}

int array_integer(const toml::node& node, const std::string& field, const TomlSource& source,
                  long long min, long long max) {
  const auto* v = node.as_integer();
  if (!v) source.fail(node, field, fmt::format("must be an integer, got {}", type_name(node)));
  const long long value = v->get();
  if (value < min || value > max) {
    source.fail(node, field, fmt::format("must be {}..{}, got {}", min, max, value));
  }
  return static_cast<int>(value);
}

TomlFields::TomlFields(const toml::table& table, std::string prefix, const TomlSource& source,
                       std::initializer_list<std::string_view> allowed)
    : table_(table), prefix_(std::move(prefix)), source_(source) {
  const toml::key* unknown = nullptr;
  for (const auto& [key, node] : table_) {
    if (std::find(allowed.begin(), allowed.end(), key.str()) != allowed.end()) continue;
    if (!unknown || key.source().begin.line < unknown->source().begin.line) unknown = &key;
  }
  if (unknown) {
    // Which keys the table takes, and the one a typo probably meant.
    const auto meant = nearest_word(unknown->str(), allowed);
    source_.fail(static_cast<int>(unknown->source().begin.line), field(unknown->str()),
                 fmt::format("unknown key{} (valid here: {})",
                             meant ? fmt::format(": did you mean {}?", *meant) : std::string(),
                             word_list(allowed)));
  }
}

int TomlFields::line() const {
  return l2::line_of(table_);
}

int TomlFields::line_of(std::string_view key) const {
  const toml::node* n = table_.get(key);
  return n ? l2::line_of(*n) : line();
}

std::string TomlFields::field(std::string_view key) const {
  return prefix_.empty() ? std::string(key) : fmt::format("{}.{}", prefix_, key);
}

void TomlFields::fail(std::string_view key, std::string_view message) const {
  source_.fail(line_of(key), field(key), message);
}

std::optional<int> TomlFields::integer(std::string_view key, long long min, long long max) const {
  const toml::node* n = table_.get(key);
  if (!n) return std::nullopt;
  return array_integer(*n, field(key), source_, min, max);
}

int TomlFields::integer(std::string_view key, long long min, long long max, int fallback) const {
  return integer(key, min, max).value_or(fallback);
}

int TomlFields::required_integer(std::string_view key, long long min, long long max) const {
  const auto v = integer(key, min, max);
  if (!v) source_.fail(line(), field(key), "missing (required)");
  return *v;
}

double TomlFields::fraction(std::string_view key, double min, double below, double fallback) const {
  const toml::node* n = table_.get(key);
  if (!n) return fallback;
  const auto v = n->value<double>();  // an integer too: 0 is a fraction
  if (!v) fail(key, fmt::format("must be a number, got {}", type_name(*n)));
  if (!(*v >= min && *v < below))
    fail(key, fmt::format("must be a number from {} up to below {}, got {}", min, below, *v));
  return *v;
}

std::optional<std::string> TomlFields::string(std::string_view key) const {
  const toml::node* n = table_.get(key);
  if (!n) return std::nullopt;
  const auto* s = n->as_string();
  if (!s) fail(key, fmt::format("must be a string, got {}", type_name(*n)));
  return s->get();
}

bool TomlFields::boolean(std::string_view key, bool fallback) const {
  const toml::node* n = table_.get(key);
  if (!n) return fallback;
  const auto* b = n->as_boolean();
  if (!b) fail(key, fmt::format("must be true or false, got {}", type_name(*n)));
  return b->get();
}

int TomlFields::choice(std::string_view key, const std::vector<std::string_view>& choices,
                       int fallback) const {
  const auto s = string(key);
  if (!s) return fallback;
  const auto it = std::find(choices.begin(), choices.end(), *s);
  if (it == choices.end()) {
    fail(key, fmt::format("must be one of {}, got \"{}\"", fmt::join(choices, ", "), *s));
  }
  return static_cast<int>(it - choices.begin());
}

const toml::array* TomlFields::array(std::string_view key) const {
  const toml::node* n = table_.get(key);
  if (!n) return nullptr;
  if (!n->is_array()) fail(key, fmt::format("must be an array, got {}", type_name(*n)));
  return n->as_array();
}

const toml::table* TomlFields::table(std::string_view key) const {
  const toml::node* n = table_.get(key);
  if (!n) return nullptr;
  if (!n->is_table()) fail(key, fmt::format("must be a table, got {}", type_name(*n)));
  return n->as_table();
}

}  // namespace l2
