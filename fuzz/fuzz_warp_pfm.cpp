// The PFM warp reader (parse_warp_pfm, docs/wall-file.md "Warping projected pictures") on
// arbitrary bytes: the first two bytes pick the display's size (1..16 each), the rest is the
// file. Out comes a map of that size whose every source position lies on the frame or is black,
// which a picture of that size then goes through; or one LayoutError line naming the file.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.hpp"
#include "image/warp_map.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/warp_file.hpp"

using l2::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const int width = 1 + data[0] % 16, height = 1 + data[1] % 16;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 2, size - 2);
  try {
    const l2::WarpMap map = l2::parse_warp_pfm(bytes, "fuzz.pfm", width, height);
    require(map.width == width && map.height == height, "a warp is the display's size");
    require(bytes.size() <= l2::max_warp_pfm_bytes(width, height),
            "a warp that parses is within the size limit");
    for (std::size_t i = 0; i < map.source.size(); i += 2) {
      const std::int32_t x = map.source[i], y = map.source[i + 1];
      if (x == l2::kWarpBlack) continue;
      require(
          x >= 0 && x <= (width - 1) * l2::kWarpOne && y >= 0 && y <= (height - 1) * l2::kWarpOne,
          "a source position lies between the edge pixels' centres");
    }
    // Applying it reads only inside the picture (ASan watches).
    l2::RgbImage in(width, height, l2::Rgb{1, 2, 3}), out;
    l2::apply_warp(map, in, out);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const l2::Rgb c = out.at(x, y);
        require(c == l2::Rgb{1, 2, 3} || c == l2::Rgb{},
                "a uniform picture warps to itself or black");
      }
    }
  } catch (const l2::LayoutError& e) {
    const std::string_view message = e.what();
    l2::fuzz::require_one_line(message, "a warp error is one line");
    require(message.rfind("fuzz.pfm", 0) == 0, "a warp error names the file first");
  }
  return 0;
}
