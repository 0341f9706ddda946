// The colour-table file parser (parse_colour_lut, docs/wall-file.md "Colour table files") on
// arbitrary text: a table of exactly 256 entries, or one LayoutError line naming the file;
// nothing else may come out of it.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.hpp"
#include "tilelayout/colour_lut.hpp"
#include "tilelayout/tile_layout.hpp"

using l2::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const l2::ColourTable table = l2::parse_colour_lut(text, "fuzz.txt");
    require(size <= l2::kMaxColourLutBytes, "a table that parses is within the size limit");
    // Applying it reads only inside its channels: every byte value of every channel.
    l2::RgbImage all(256, 1);
    for (int i = 0; i < 256; ++i) {
      const auto v = static_cast<std::uint8_t>(i);
      all.set(i, 0, {v, v, v});
    }
    l2::apply_colour(table, all, all);
    require(all.at(255, 0).b == table.channel[2][255], "a byte goes through its channel's table");
  } catch (const l2::LayoutError& e) {
    const std::string_view message = e.what();
    l2::fuzz::require_one_line(message, "a colour-table error is one line");
    require(message.rfind("fuzz.txt", 0) == 0, "a colour-table error names the file first");
  }
  return 0;
}
