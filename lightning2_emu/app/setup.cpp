#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "commands.hpp"
#include "frame_files.hpp"

namespace l2 {

Setup make_setup(const CommonOptions& o) {
  if (o.displays.empty() == o.wall.empty()) {
    throw std::invalid_argument("give either --displays WxH[,WxH...] or --wall W.toml");
  }
  Setup setup;
  const InputLimit limit = parse_size(o.board_max, "--board-max");
  setup.config.background = parse_colour(o.background, "--background");
  setup.config.workers = o.threads;
  if (!o.wall.empty()) {
    throw std::invalid_argument("--wall: wall files are not supported by this build yet");
  }
  setup.config.displays = parse_display_list(o.displays);
  if (!o.groups.empty()) apply_group_list(o.groups, setup.config.displays);
  const int inputs = static_cast<int>(o.inputs.size());
  if (o.mesh.empty()) {
    setup.config.mesh = Mesh::fit(inputs, static_cast<int>(setup.config.displays.size()), limit);
  } else {
    const InputLimit rc = parse_size(o.mesh, "--mesh");
    setup.config.mesh = Mesh(rc.width, rc.height, limit);
    if (inputs > setup.config.mesh.input_count()) {
      throw MeshError(fmt::format("{} inputs given, the mesh ({}) has {}", inputs,
                                  setup.config.mesh.describe(), setup.config.mesh.input_count()));
    }
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
