// `lightning2_emu route --verify`: the routed displays checked against the wall's plan, pixel
// by pixel through the routing test pattern (verify/routing_check.hpp).
#include <iostream>

#include "commands.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/several_meshes.hpp"
#include "tilelayout/wall_file.hpp"
#include "verify/verify_run.hpp"

namespace l2 {

int verify_route(const CommonOptions& o, std::span<const RgbImage> frames, const Router& router) {
  const Wall wall = load_wall(o.wall);
  require_one_mesh(wall, "lightning2_emu");
  const TileLayout layout = plan_layout(wall);
  for (const std::string& w : layout.warnings) std::cerr << "lightning2_emu: " << w << "\n";
  std::vector<const RgbImage*> routed;
  for (const Display& d : layout.wall.displays) {
    const int index = router.index_of_display(d.id);
    routed.push_back(index < 0 ? nullptr : &router.display(index).back());
  }
  return verify_and_report(layout, frames, routed, o.out, std::cout) ? 0 : kExitRoutingWrong;
}

}  // namespace l2
