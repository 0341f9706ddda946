// The wall-file parser (TOML, docs/wall-file.md) on arbitrary text: a wall, or one LayoutError
// line naming the file; nothing else may come out of it.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_file.hpp"

using l2::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const l2::Wall wall = l2::parse_wall(text, "fuzz.toml");
    require(!wall.displays.empty(), "a wall that parses has displays");
  } catch (const l2::LayoutError& e) {
    const std::string_view message = e.what();
    l2::fuzz::require_one_line(message, "a wall-file error is one line");
    require(message.rfind("fuzz.toml", 0) == 0, "a wall-file error names the file first");
  }
  return 0;
}
