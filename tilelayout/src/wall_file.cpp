#include "tilelayout/wall_file.hpp"

#include <fmt/format.h>

#include <string>

#include "tilelayout/tile_layout.hpp"
#include "wall_sections.hpp"

namespace l2 {

Wall parse_wall(std::string_view toml_text, const std::filesystem::path& path_for_messages) {
  const TomlSource source{path_for_messages.string()};
  const toml::table doc = parse_toml(toml_text, source);
  const TomlFields top(doc, "", source,
                       {"name", "canvas", "display_grid", "display", "displays", "tiling",
                        "pipeservers", "mesh", "depth", "overlay", "balance", "blend", "stereo"});
  Wall wall;
  wall.source = path_for_messages;
  wall.name = top.string("name").value_or(path_for_messages.stem().string());
  read_stereo(top, wall);
  read_displays(top, wall);
  read_display_clocks(top, wall);
  read_stereo_displays(top, wall);
  read_canvas(top, wall);
  read_tiling(top, wall);
  read_pipeservers_and_mesh(top, wall);
  read_compositing(top, wall);
  read_balance(top, wall);
  read_blend(top, wall);
  read_meshes(top, wall);
  check_stereo(top, wall);
  return wall;
}

Wall load_wall(const std::filesystem::path& path) {
  return parse_wall(read_toml_file(path, "a wall file"), path);
}

Wall default_wall() {
  return parse_wall(default_wall_toml(), "walls/kd-2x2.toml (built in)");
}

}  // namespace l2
