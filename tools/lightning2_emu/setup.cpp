#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "commands.hpp"
#include "lightning2_emu/frame_files.hpp"
#include "lightning2_emu/wall_emulator.hpp"
#include "tilelayout/several_meshes.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {

Setup make_setup(const CommonOptions& o) {
  if (o.displays.empty() == o.wall.empty()) {
    throw std::invalid_argument("give either --displays WxH[,WxH...] or --wall W.toml");
  }
  Setup setup;
  InputLimit limit = parse_size(o.board_max, "--board-max");
  setup.config.background = parse_colour(o.background, "--background");
  setup.config.workers = o.threads;
  const int inputs = static_cast<int>(o.inputs.size());
  int mesh_inputs = inputs;
  if (!o.wall.empty()) {
    // The wall decides displays, swap groups, board limit and, through its pipeserver count,
    // how many board rows the mesh has.
    const Wall wall = load_wall(o.wall);
    require_one_mesh(wall, "lightning2_emu");
    if (!o.groups.empty()) {
      throw std::invalid_argument("--groups: with --wall the swap groups come from the wall");
    }
    setup.from_wall = true;
    setup.canvas_width = wall.canvas_width;
    setup.canvas_height = wall.canvas_height;
    setup.config.displays = display_specs(wall);
    for (const Display& d : wall.displays)
      setup.placements.push_back({d.id, d.canvas_x, d.canvas_y});
    limit = {wall.board_max_width, wall.board_max_height};
    mesh_inputs = wall.pipeserver_count;
  } else {
    setup.config.displays = parse_display_list(o.displays);
    if (!o.groups.empty()) apply_group_list(o.groups, setup.config.displays);
  }
  const int displays = static_cast<int>(setup.config.displays.size());
  try {
    if (o.mesh.empty()) {
      setup.config.mesh = Mesh::fit(mesh_inputs, displays, limit);
    } else {
      const InputLimit rc = parse_size(o.mesh, "--mesh");
      setup.config.mesh = Mesh(rc.width, rc.height, limit);
    }
  } catch (const MeshError& e) {
    // The mesh checks rows, columns, board limit and display count; without --wall they all
    // come from the options (--mesh, --board-max, --displays): a usage error, exit 2.
    if (setup.from_wall) throw;
    throw std::invalid_argument(fmt::format("--mesh/--board-max/--displays: {}", e.what()));
  }
  if (inputs > setup.config.mesh.input_count()) {
    throw MeshError(fmt::format("{} inputs given, the mesh ({}) has {}", inputs,
                                setup.config.mesh.describe(), setup.config.mesh.input_count()));
  }
  return setup;
}

RgbImage compose_wall(const Setup& setup, const std::vector<const RgbImage*>& shown_by_id) {
  const Rgb kMullion{40, 40, 40};
  int w = setup.canvas_width, h = setup.canvas_height;
  for (const auto& p : setup.placements) {
    const RgbImage& shown = *shown_by_id.at(p.display);
    w = std::max(w, p.x + shown.width());
    h = std::max(h, p.y + shown.height());
  }
  RgbImage wall(std::max(w, 1), std::max(h, 1), kMullion);
  for (const auto& p : setup.placements) {
    const RgbImage& shown = *shown_by_id.at(p.display);
    for (int y = 0; y < shown.height(); ++y) {
      if (p.y + y < 0) continue;
      for (int x = 0; x < shown.width(); ++x) {
        if (p.x + x >= 0) wall.set(p.x + x, p.y + y, shown.at(x, y));
      }
    }
  }
  return wall;
}

}  // namespace l2
