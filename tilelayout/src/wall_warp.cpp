// `warp` of a [[display]] entry (docs/wall-file.md, "Warping projected pictures"): the PFM file
// it names, relative to the wall file as a colour table's is, read once when the wall is read and
// kept as the display's fixed-point map.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <string>

#include "tilelayout/tile_layout.hpp"
#include "tilelayout/warp_file.hpp"
#include "wall_sections.hpp"

namespace l2 {

void read_warp(const TomlFields& f, Display& d) {
  if (!f.has("warp")) return;
  d.warp = *f.string("warp");
  if (d.warp.empty()) f.fail("warp", "must name a PFM warp file, got \"\"");
  const std::filesystem::path path = std::filesystem::path(f.source().file).parent_path() / d.warp;
  std::string bytes;
  try {
    // Only a file, as for a colour table: a pipe named here would hold the wall's readers. The
    // limit is what a warp of this display's size can be, so a wrong or hostile file is
    // refused before it is read to the end.
    std::error_code error;
    if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
      throw LayoutError(fmt::format("{}: not a regular file: a warp is a PFM file", path.string()));
    bytes =
        read_toml_file(path, "a PFM warp for this display", max_warp_pfm_bytes(d.width, d.height));
  } catch (const LayoutError& e) {
    f.fail("warp", e.what());
  }
  WarpMap map = parse_warp_pfm(bytes, path.string(), d.width, d.height);
  if (!is_identity(map)) d.warp_map = std::make_shared<const WarpMap>(std::move(map));
}

}  // namespace l2
