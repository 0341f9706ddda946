// tilelayout import (Tide, SAGE2, nDisplay JSON; docs/wall-import.md) on arbitrary bytes: the
// first byte picks the format (told from the content, or one of the three forced), the rest is
// the file. Out comes a wall file that parse_wall reads, with a host for every pipeserver when
// the file names hosts, or one LayoutError line naming the file; nothing else.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "fuzz_check.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_file.hpp"
#include "tilelayout/wall_import.hpp"

using l2::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::optional<l2::ImportFormat> format;
  if (data[0] % 4 != 0) format = static_cast<l2::ImportFormat>(data[0] % 4 - 1);
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const l2::ImportedWall imported = l2::import_wall(text, "fuzz.json", format);
    for (const std::string& note : imported.notes)
      l2::fuzz::require_one_line(note, "an import note is one line");
    // A wall-file error here names fuzz.toml, not fuzz.json: the catch below reports it.
    const l2::Wall wall = l2::parse_wall(imported.toml, "fuzz.toml");
    require(!wall.displays.empty() && wall.displays.size() <= 64,
            "an imported wall has 1..64 displays");
    require(
        imported.hosts.empty() || static_cast<int>(imported.hosts.size()) == wall.pipeserver_count,
        "every pipeserver of an imported wall that names hosts has one");
  } catch (const l2::LayoutError& e) {
    const std::string_view message = e.what();
    l2::fuzz::require_one_line(message, "an import error is one line");
    require(message.rfind("fuzz.json: ", 0) == 0, "an import error names the file first");
  }
  return 0;
}
