#include "lightning2_emu/wall_emulator.hpp"

#include <algorithm>

namespace l2 {
namespace {

DisplaySpec spec(const Display& d) {
  return {d.id, d.width, d.height, d.swap_group};
}

}  // namespace

std::vector<DisplaySpec> display_specs(const Wall& wall) {
  std::vector<DisplaySpec> out;
  for (const Display& d : wall.displays) out.push_back(spec(d));
  return out;
}

std::vector<DisplaySpec> display_specs(const Wall& wall, std::span<const int> ids) {
  std::vector<DisplaySpec> out;
  for (const Display& d : wall.displays) {
    if (std::find(ids.begin(), ids.end(), d.id) != ids.end()) out.push_back(spec(d));
  }
  return out;
}

std::vector<int> display_ids(const Wall& wall) {
  std::vector<int> ids;
  for (const Display& d : wall.displays) ids.push_back(d.id);
  return ids;
}

Mesh wall_mesh(const Wall& wall) {
  return Mesh::fit(wall.pipeserver_count, static_cast<int>(wall.displays.size()),
                   {wall.board_max_width, wall.board_max_height});
}

EmulatorConfig emulator_config(const Wall& wall, int workers) {
  EmulatorConfig config;
  config.mesh = wall_mesh(wall);
  config.displays = display_specs(wall);
  config.workers = workers;
  return config;
}

}  // namespace l2
