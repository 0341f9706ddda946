// Colour matching per display: `gain`, `offset` and `lut` of a [[display]] entry, or one table of
// them per display in [display_grid]'s `colour` list (docs/wall-file.md, "Colour matching").
// Everything a display's correction was written as becomes its one ColourTable here.
#include <fmt/format.h>

#include <filesystem>
#include <string>

#include "tilelayout/colour_lut.hpp"
#include "tilelayout/tile_layout.hpp"
#include "wall_sections.hpp"

namespace l2 {
namespace {

// Three numbers of `key` (an array of exactly three), each checked by `one`.
template <typename T, typename One>
std::array<T, 3> three(const TomlFields& f, std::string_view key, std::string_view what, One one) {
  const toml::node* n = f.node(key);
  const toml::array* a = n->as_array();
  if (!a) f.fail(key, fmt::format("needs 3 {}, got {}", what, type_name(*n)));
  if (a->size() != 3) f.fail(key, fmt::format("needs 3 {}, got {}", what, a->size()));
  std::array<T, 3> values{};
  for (std::size_t c = 0; c < 3; ++c)
    values[c] = one(*a->get(c), fmt::format("{}[{}]", f.field(key), c));
  return values;
}

// The table file `lut` names, relative to the wall file. A file that cannot be read is the wall
// file's error (its line and field); what is wrong inside the table names the table's own line.
ColourTable read_lut(const TomlFields& f, const std::string& lut) {
  const std::filesystem::path path = std::filesystem::path(f.source().file).parent_path() / lut;
  std::string text;
  try {
    // Only a file: a device or a pipe named here (/dev/stdin) would hold every program that
    // reads the wall until someone writes to it.
    std::error_code error;
    if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
      throw LayoutError(
          fmt::format("{}: not a regular file: a colour table is a text file", path.string()));
    text = read_toml_file(path, "a colour table");
  } catch (const LayoutError& e) {
    f.fail("lut", e.what());
  }
  return parse_colour_lut(text, path.string());
}

}  // namespace

ColourMatch read_colour(const TomlFields& f) {
  ColourMatch m;
  if (f.has("lut")) {
    if (f.has("gain") || f.has("offset")) f.fail("lut", "use either lut or gain/offset, not both");
    m.kind = ColourMatch::Kind::Lut;
    m.lut = *f.string("lut");
    if (m.lut.empty()) f.fail("lut", "must name a colour table file, got \"\"");
    m.table = read_lut(f, m.lut);
    return m;
  }
  if (!f.has("gain") && !f.has("offset")) return m;
  m.kind = ColourMatch::Kind::Gain;
  const TomlSource& source = f.source();
  if (f.has("gain")) {
    m.gain = three<double>(
        f, "gain", fmt::format("numbers 0..{}", kMaxGain),
        [&](const toml::node& n, const std::string& field) {
          const auto v = n.value<double>();  // an integer too
          if (!v) {
            source.fail(n, field,
                        fmt::format("must be a number 0..{}, got {}", kMaxGain, type_name(n)));
          }
          if (!(*v >= 0 && *v <= kMaxGain)) {
            source.fail(n, field, fmt::format("must be a number 0..{}, got {}", kMaxGain, *v));
          }
          return *v;
        });
  }
  if (f.has("offset")) {
    m.offset = three<int>(f, "offset", fmt::format("integers -{0}..{0}", kMaxOffset),
                          [&](const toml::node& n, const std::string& field) {
                            return array_integer(n, field, source, -kMaxOffset, kMaxOffset);
                          });
  }
  m.table = colour_table_from_gain(m.gain, m.offset);
  return m;
}

void read_grid_colour(const TomlFields& grid, std::vector<Display>& displays) {
  const toml::array* list = grid.array("colour");
  if (!list) return;
  const int n = static_cast<int>(displays.size());
  if (static_cast<int>(list->size()) != n) {
    grid.fail("colour", fmt::format("needs {} entries (one per display, {{}} for none), got {}", n,
                                    list->size()));
  }
  for (int i = 0; i < n; ++i) {
    const toml::node& entry = *list->get(static_cast<std::size_t>(i));
    const std::string field = fmt::format("{}[{}]", grid.field("colour"), i);
    if (!entry.is_table()) {
      grid.source().fail(entry, field,
                         fmt::format("must be a table ({{gain = [...]}}, "
                                     "{{lut = \"...\"}} or {{}}), got {}",
                                     type_name(entry)));
    }
    const TomlFields f(*entry.as_table(), field, grid.source(), {"gain", "offset", "lut"});
    displays[static_cast<std::size_t>(i)].colour = read_colour(f);
  }
}

}  // namespace l2
