// [balance]: how the tiling follows the load (balance/ does the balancing).
#include <fmt/format.h>

#include <vector>

#include "wall_sections.hpp"

namespace l2 {

void read_balance(const TomlFields& top, Wall& wall) {
  const toml::table* table = top.table("balance");
  if (!table) return;
  const TomlFields f(*table, "balance", top.source(),
                     {"mode", "assignment", "survive_host_loss", "resistance", "tile_cost"});
  wall.balance.line = f.line();
  const std::vector<std::string_view> modes(std::begin(kBalanceModeNames),
                                            std::end(kBalanceModeNames));
  wall.balance.mode = static_cast<BalanceMode>(f.choice("mode", modes, 0));
  wall.balance.heaviest_first = f.choice("assignment", {"policy", "heaviest-first"}, 0) == 1;
  wall.balance.survive_host_loss = f.boolean("survive_host_loss", false);
  // Below 1: a resistance of 1 would never take a layout, and a tile cost of 1 is all overhead.
  wall.balance.resistance = f.fraction("resistance", 0, 1, 0);
  wall.balance.tile_cost = f.fraction("tile_cost", 0, 1, 0);
  const bool balancing = wall.balance.balancing();
  // Only a balancing run re-plans, so only it can hand a dead host's tiles to the others.
  if (wall.balance.survive_host_loss && !balancing) {
    f.fail("survive_host_loss",
           "needs balancing: mode = \"strips\" or \"kd\", or assignment = \"heaviest-first\"");
  }
  // Depth and overlay tiles are shared out by layer and by rectangle, not by render time.
  if (balancing && (wall.depth_layers != 0 || wall.overlay)) {
    f.fail(f.has("mode") ? "mode" : "assignment",
           fmt::format("cannot balance a wall with [{}]: its tiles are shared by layer, not by "
                       "render time",
                       wall.depth_layers != 0 ? "depth" : "overlay"));
  }
}

}  // namespace l2
